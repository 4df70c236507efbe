mod c3 {
    ga_macros::algebra! {
        basis = [eo, e1, ei];
        metric = [[0, 0, -1], [0, 1, 0], [-1, 0, 0]];
        type Vector { blades = [eo, e1, ei] }
        // Every blade is a constant: nothing is stored.
        type Origin { blades = [eo], constants = { eo = 1 } }
    }
}

fn main() {}
