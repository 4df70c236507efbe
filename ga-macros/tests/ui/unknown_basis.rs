mod g3 {
    ga_macros::algebra! {
        basis = [e1, e2, e3];
        diagonal = [1, 1, 1];
        type Vector { blades = [e1, e2, e4] }
    }
}

fn main() {}
