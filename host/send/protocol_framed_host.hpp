// Framed protocol, host side (the shared parts are in protocol_framed.hpp).
#pragma once

#include <string>

#include "protocol_raw.hpp"

namespace minrt::send {

TransferResult run_framed(Exchange& ex, const std::string& scene_text, const ImageSpec& spec);

}  // namespace minrt::send
