//! The operation rows of the harness: ga-benchmark's binary and unary operation sets on CGA f64
//! blades of every grade, timed by `benches::peer_ops_set` and `benches::peer_ops_unary`
//! (compiled in the library, apart from this example; see there) and recorded here.

use crate::Record;
pub(crate) use benches::peer_ops_set::{blade, pairs, product_name, products};
pub(crate) use benches::peer_ops_unary::{unary_name, UNARY};
use std::collections::BTreeMap;

/// Times every operation row and records it.
pub(crate) fn op_rows(inp: &BTreeMap<&str, Vec<f64>>, rec: &mut Record) {
    let side = |s: char| -> [&[f64]; 6] {
        std::array::from_fn(|g| &inp[format!("cga.blade{g}_{s}").as_str()][..])
    };
    let rows = benches::peer_ops_set::op_rows(side('a'), side('b'));
    let unary = benches::peer_ops_unary::unary_rows(side('a'));
    for (key, ns, out) in rows.into_iter().chain(unary) {
        rec.times.push((key.clone(), ns));
        rec.outputs.push((key, out));
    }
}
