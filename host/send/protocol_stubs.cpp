#include "protocol_course_host.hpp"
#include "protocol_framed_host.hpp"
namespace minrt::send {
TransferResult run_course(Exchange&, const std::string&, const std::string&, const CourseHostOptions&, const ImageSpec&) {
  TransferResult r; r.message = "course protocol not implemented yet"; return r;
}
TransferResult run_framed(Exchange&, const std::string&, const ImageSpec&) {
  TransferResult r; r.message = "framed protocol not implemented yet"; return r;
}
}
