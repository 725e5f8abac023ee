"""The machine the accuracy figures are measured on, for the reports' footers."""


def cpu_model():
    """The CPU as /proc/cpuinfo names it."""
    try:
        with open("/proc/cpuinfo") as info:
            for line in info:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"
