// The host's side of each format in the registry (formats/registry.hpp), in
// its order: the only place the host names its formats' code. A format
// added to the registry without its row here does not compile.
#pragma once

#include "cs418_host.hpp"
#include "eastray_host.hpp"
#include "jaworski_host.hpp"
#include "minirt_host.hpp"
#include "sld_host.hpp"

namespace minrt::host {

inline constexpr HostFormat kHostFormats[] = {
    {formats::FormatId::kSld, nullptr, &stream_sld},
    {formats::FormatId::kCs418, &prepare_cs418, nullptr},
    {formats::FormatId::kJaworski, &prepare_jaworski, nullptr},
    {formats::FormatId::kMinirt, &prepare_minirt, nullptr},
    {formats::FormatId::kEastray, &prepare_eastray, nullptr},
};

static_assert(formats::follows_registry(kHostFormats), "one row per registered format, in its order");

inline const HostFormat& host_format(formats::FormatId id) { return kHostFormats[static_cast<std::size_t>(id)]; }

}  // namespace minrt::host
