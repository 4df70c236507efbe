mod g2 {
    ga_macros::algebra! {
        basis = [e1, e2];
        metric = [[1, 0.5],
                  [0, 1]];
        type Vector { blades = [e1, e2] }
    }
}

fn main() {}
