mod c3 {
    ga_macros::algebra! {
        basis = [eo, e1, ei];
        metric = [[0, 0, -1],
                  [0, 1],
                  [-1, 0, 0]];
        type Vector { blades = [eo, e1, ei] }
    }
}

fn main() {}
