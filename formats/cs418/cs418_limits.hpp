// Bounds of the CS418 reader, each defined once. The assignment sets none
// and asks for no error checking; these are what the host and the board can
// hold, and the reader says so with a warning when a scene asks for more.
#pragma once

namespace minrt::cs418 {

inline constexpr int kMaxLineBytes = 4096;
inline constexpr int kMaxFileName = 255;  // png and texture names
// Recursion depths the stack holds (the board's is 32 KiB): deeper
// requests are taken as these, with a warning.
inline constexpr int kMaxBounces = 64;
inline constexpr int kMaxGiDepth = 16;
inline constexpr int kMaxTextures = 64;

}  // namespace minrt::cs418
