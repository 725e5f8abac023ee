// What a text format's board path (cs418_board, jaworski_board,
// minirt_board, eastray_board, board_formats) reports: the image was
// sent, the scene was refused (the Diagnostic says where and why), or the
// scene did not fit the arena.
#pragma once

namespace minrt::fw {

enum class SceneResult { kOk, kSceneError, kOutOfMemory };

}  // namespace minrt::fw
