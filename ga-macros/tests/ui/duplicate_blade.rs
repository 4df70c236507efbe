mod g3 {
    ga_macros::algebra! {
        basis = [e1, e2, e3];
        diagonal = [1, 1, 1];
        type Bivector { blades = [e12, e23, e21] }
    }
}

fn main() {}
