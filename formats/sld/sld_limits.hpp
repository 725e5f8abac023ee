// Limits of an SLD scene. The format allows 60 objects; the original holds
// 50 AND networks. The other bounds are ours: the original had none (it grew
// OCaml arrays), so we picked values well above anything a course scene uses
// and reject more with an error instead of overrunning fixed storage.
#pragma once

namespace minrt::limits {

inline constexpr int kMaxObjects = 60;
// AND networks an OR network may use: the original holds 50 (indices 0..49).
inline constexpr int kMaxAndNetworks = 50;
// AND networks a file may define. More than 50 can only be harmless extras
// (nothing may refer to them), but a 60-object scene naturally has one per
// object, so we read that many and ignore the unused ones with a warning.
inline constexpr int kMaxAndNetworkDefinitions = 64;
// Entries of one AND network (object indices), not counting the -1 terminator.
inline constexpr int kMaxAndNetworkLength = 60;
// OR networks (rows of the OR matrix), not counting the terminating row.
inline constexpr int kMaxOrNetworks = 64;
// Entries of one OR network: the range primitive plus AND network indices.
inline constexpr int kMaxOrNetworkLength = 1 + kMaxAndNetworkDefinitions;
// Longest accepted number token; the original overflowed its stack on 1 MB.
inline constexpr int kMaxTokenLength = 256;

// Object index meaning "no range primitive" in an OR network.
inline constexpr int kNoRangePrimitive = 99;

}  // namespace minrt::limits
