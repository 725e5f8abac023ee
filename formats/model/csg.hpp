// CSG trees of the general model over quadric solids (quadric.hpp): leaves
// name a solid; OR and AND combine their children; a RANGE node is a bound
// (a solid a ray must meet) that combines its children as its parent does;
// the top node's children are independent objects. EASTRAY blocks are these
// (formats/eastray); the min-rt core's AND/OR networks are the precedent.
#pragma once

#include <stdint.h>

namespace minrt::model {

inline constexpr int32_t kNoNode = -1;

enum class NodeKind : uint8_t { kLeaf, kOr, kAnd, kRange, kTop };

// Children are linked by `next` (kNoNode ends a list).
struct CsgNode {
  NodeKind kind;
  NodeKind mode;        // how the children combine: kOr, kAnd or kTop
  int32_t parent;
  int32_t first_child, last_child, next;
  int32_t primitive;    // leaf: the solid; range: its bounding solid
};

}  // namespace minrt::model
