// ga-benchmark's operation set on GATL (gatl_ops.hpp), one object per left grade: built by
// run.sh with -DGATL_OPS_LEFT=GA for GA in 0..5 (one translation unit for the whole set needs
// many GiB of compiler memory), linked with gatl.cpp, which calls `gatl_ops::rows<GA>`.
#include "gatl_common.hpp"
#include "gatl_ops.hpp"

#ifndef GATL_OPS_LEFT
#error "build with -DGATL_OPS_LEFT=GA (0..5)"
#endif

namespace gatl_ops {

template <int GA> void rows(Record &rec, Input &in, double &stray);

// The binary rows (GA, 0..5) and the unary rows of grade GA.
template <>
void rows<GATL_OPS_LEFT>(Record &rec, Input &in, double &stray) {
  auto l = side(in, 'a'), r = side(in, 'b');
  row_of_pairs<GATL_OPS_LEFT>(rec, l, r, stray, std::make_integer_sequence<int, 6>{});
  unary_rows<GATL_OPS_LEFT>(rec, std::get<GATL_OPS_LEFT>(l), stray);
}

}  // namespace gatl_ops
