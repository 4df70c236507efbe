//! The operation rows of the harness: ga-benchmark's binary operation set on CGA f64 blades,
//! timed by `benches::peer_ops_set` (compiled in the library, apart from this example; see
//! there) and recorded here.

use crate::Record;
pub(crate) use benches::peer_ops_set::{blade, product_name, PAIRS};
use std::collections::BTreeMap;

/// Times every operation row and records it.
pub(crate) fn op_rows(inp: &BTreeMap<&str, Vec<f64>>, rec: &mut Record) {
    let rows = benches::peer_ops_set::op_rows(
        &inp["cga.vector_a"],
        &inp["cga.vector_b"],
        &inp["cga.blade2_a"],
        &inp["cga.blade2_b"],
        &inp["cga.blade4"],
    );
    for (key, ns, out) in rows {
        rec.times.push((key.clone(), ns));
        rec.outputs.push((key, out));
    }
}
