// Port discovery on the recorded sysfs tree in data/sysfs (three USB serial
// adapters, an 8250 port with a UART and one without, a virtual console) and
// libusb on this machine.
#include <catch2/catch.hpp>

#include "port_discovery.hpp"

using namespace minrt::send;

namespace {
const std::string kSys = HS_DATA_DIR "/sysfs";
const std::string kDev = HS_DATA_DIR "/dev";

const PortInfo* find(const std::vector<PortInfo>& ports, const std::string& name) {
  for (const auto& p : ports)
    if (p.name == name) return &p;
  return nullptr;
}
}  // namespace

TEST_CASE("serial ports are found in a recorded sysfs tree", "[discovery]") {
  const auto ports = list_serial_ports(kSys, kDev);
  REQUIRE(ports.size() == 5);  // tty0 has no device link
  CHECK(find(ports, "tty0") == nullptr);

  const PortInfo* ftdi = find(ports, "ttyUSB0");
  REQUIRE(ftdi != nullptr);
  CHECK(ftdi->device == "/dev/ttyUSB0");
  CHECK(ftdi->usb);
  CHECK(ftdi->vid == 0x0403);
  CHECK(ftdi->pid == 0x6001);
  CHECK(ftdi->serial == "A50285BI");
  CHECK(ftdi->product == "FT232R USB UART");
  CHECK(ftdi->manufacturer == "FTDI");
  CHECK(ftdi->interface == 0);
  CHECK(ftdi->driver == "ftdi_sio");
  CHECK(ftdi->busnum == 1);
  CHECK(ftdi->devnum == 5);
  CHECK(ftdi->by_id == "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0");

  const PortInfo* acm = find(ports, "ttyACM0");
  REQUIRE(acm != nullptr);
  CHECK(acm->vid == 0x2e8a);
  CHECK(acm->pid == 0x000a);
  CHECK(acm->driver == "cdc_acm");
  CHECK(acm->by_id == "/dev/serial/by-id/usb-Raspberry_Pi_Pico_E6614103E7-if00");

  const PortInfo* legacy = find(ports, "ttyS0");
  REQUIRE(legacy != nullptr);
  CHECK_FALSE(legacy->usb);
  CHECK(legacy->driver == "serial8250");
  CHECK(legacy->uart_type == 4);
  CHECK(port_present(*legacy));
  const PortInfo* placeholder = find(ports, "ttyS1");
  REQUIRE(placeholder != nullptr);
  CHECK(placeholder->uart_type == 0);
  CHECK_FALSE(port_present(*placeholder));
  CHECK(port_present(*ftdi));

  CHECK(find(ports, "ttyUSB1")->by_id.empty());
  CHECK_THAT(format_port(*ftdi), Catch::Contains("usb:0403:6001:A50285BI") && Catch::Contains("by-id"));
}

TEST_CASE("usb:VID:PID[:SERIAL] selects a tty", "[discovery]") {
  std::string dev, err;
  CHECK(resolve_usb_port("usb:2e8a:000a", kSys, dev, err, kDev));
  CHECK(dev == "/dev/ttyACM0");
  CHECK(resolve_usb_port("usb:0403:6001:B0001", kSys, dev, err, kDev));
  CHECK(dev == "/dev/ttyUSB1");
  CHECK(resolve_usb_port("usb:0403:6001:A50285BI", kSys, dev, err, kDev));
  CHECK(dev == "/dev/ttyUSB0");

  CHECK_FALSE(resolve_usb_port("usb:0403:6001", kSys, dev, err, kDev));
  CHECK_THAT(err, Catch::Contains("several") && Catch::Contains("/dev/ttyUSB0") && Catch::Contains("/dev/ttyUSB1"));
  CHECK_FALSE(resolve_usb_port("usb:1234:5678", kSys, dev, err, kDev));
  CHECK_THAT(err, Catch::Contains("no serial port matches"));
  CHECK_FALSE(resolve_usb_port("usb:xyz:1", kSys, dev, err, kDev));
  CHECK_THAT(err, Catch::Contains("bad USB port"));
  CHECK_FALSE(resolve_usb_port("usb:0403", kSys, dev, err, kDev));
}

TEST_CASE("a missing sysfs root gives an empty list", "[discovery]") {
  CHECK(list_serial_ports("/nonexistent-sysfs").empty());
}

TEST_CASE("libusb enumeration runs and returns a list", "[discovery]") {
  bool available = false;
  const auto devices = enumerate_usb(available);
  // No USB on a build machine is fine; the call must work and be consistent.
  for (const auto& d : devices) CHECK(d.bus >= 0);
  SUCCEED("libusb " << (available ? "available" : "unavailable") << ", " << devices.size() << " devices");
}

TEST_CASE("the live system's ports can be listed", "[discovery]") {
  const auto ports = list_serial_ports("/sys");
  for (const auto& p : ports) CHECK(p.device.rfind("/dev/", 0) == 0);
}
