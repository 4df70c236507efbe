mod c3 {
    ga_macros::algebra! {
        basis = [eo, e1, ei];
        metric = [[0, 0, -1], [0, 1, 0], [-1, 0, 0]];
        type Point { blades = [e1, ei], constants = { eo = 1 } }
    }
}

fn main() {}
