// Bounds the CS418 reader enforces, each defined once. The assignment sets
// none; these keep recursion, sampling and file names within what the host
// and the board can do, and say so clearly when a scene asks for more.
#pragma once

namespace minrt::cs418 {

inline constexpr int kMaxLineBytes = 4096;
inline constexpr int kMaxFileName = 255;  // png and texture names
inline constexpr int kMaxBounces = 64;    // recursion depth (each level uses stack)
inline constexpr int kMaxGiDepth = 16;
inline constexpr int kMaxSamples = 65536;  // aa
inline constexpr int kMaxTextures = 64;

}  // namespace minrt::cs418
