#include "standin_protocols.hpp"
namespace standin {
bool serve_course(Link&, const RenderFn&) { return false; }
bool serve_framed(Link&, const minrt::RenderOptions&, const RenderFn&) { return false; }
}
