// `exp_log = required` on a six-dimensional Euclidean algebra: its bivector can have three
// commuting parts, so there is no closed-form exp/log; the error names the type at its name.
mod g6 {
    ga_macros::algebra! {
        exp_log = required;
        basis = [e1, e2, e3, e4, e5, e6];
        diagonal = [1, 1, 1, 1, 1, 1];
        type Bivector { blades = [e12, e34, e56] }
    }
}

fn main() {}
