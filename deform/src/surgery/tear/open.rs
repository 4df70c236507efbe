//! Opening the incision (Algorithm 2, steps 8-9): every inner incision point is split into two
//! lips, over the welded surface. Around each point the faces on the left of the incision
//! (seen along it with the surface's orientation) keep its vertices, those on the right get
//! copies: a copy of each vertex (seam copy included) that has faces on both sides, while a
//! seam copy whose faces all lie on the right already is the right lip and only changes label.
//! The lips can then be pulled apart along the step planes' normals.

use super::super::soup::Soup;
use super::super::SurgeryError;
use super::seams::{Seams, LIP};
use glam::DVec3;
use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap, HashSet};
use std::f64::consts::PI;

/// The faces around an incision point on its left and on its right.
type Sides = (Vec<u32>, Vec<u32>);

/// Open the incision (soup vertices, first scalpel point to last): its inner points get a
/// right lip, and with `open` the lips move apart by up to `open` (a sine taper, zero at the
/// tips). The incision is left listing the left lip. Returns how many points were split.
///
/// A scalpel that goes back along its own incision visits points twice: each is split and
/// moved once, at its first visit, and the taper follows the incision's distinct edges (the
/// distance to its nearest tip), so a slit traced there and back opens as the slit traced once.
///
/// # Errors
/// [`SurgeryError::Broken`] on inconsistent bookkeeping; [`SurgeryError::BadMesh`] when a
/// moved vertex cannot be mapped back to the rest pose.
pub(super) fn open_incision(
    soup: &mut Soup,
    seams: &mut Seams,
    incision: &mut [u32],
    planes: &[(DVec3, DVec3)],
    open: f64,
) -> Result<usize, SurgeryError> {
    let m = incision.len();
    if m < 3 {
        return Ok(0);
    }
    let labels: Vec<u32> = incision.iter().map(|&v| seams.label(v)).collect();
    let path: HashSet<(u32, u32)> = labels
        .windows(2)
        .map(|w| (w[0].min(w[1]), w[0].max(w[1])))
        .collect();
    // How far each point opens, before anything moves.
    let taper = taper(soup, incision, &labels);
    // The sides around every point, found before any is split: splitting one unlinks the
    // faces along its incision edges, which breaks the fans of its neighbours on the path.
    let sided: Vec<Option<Sides>> = (1..m - 1)
        .map(|j| sides(soup, seams, labels[j], labels[j + 1], &path))
        .collect::<Result<_, _>>()?;
    // The left lip each point split so far is listed as.
    let mut opened: HashMap<u32, u32> = HashMap::new();
    for (j, sided) in (1..m - 1).zip(sided) {
        let l = labels[j];
        if let Some(&v) = opened.get(&l) {
            incision[j] = v;
            continue;
        }
        let Some((left, right)) = sided else {
            continue;
        };
        let lip = LIP + j as u32;
        let (near, far) = divide(soup, seams, l, &left, &right, lip)?;
        // A seam copy whose faces all lie on the right is the right lip now.
        if far.contains(&incision[j]) {
            if let Some(&v) = near.first() {
                incision[j] = v;
            }
        }
        opened.insert(l, incision[j]);
        if open != 0.0 {
            let w = 0.5 * open * taper[j];
            let n = opening_direction(soup, planes, incision[j], left[0]);
            let base = soup.at(incision[j]);
            for (group, sign) in [(&near, 1.0), (&far, -1.0)] {
                for &x in group {
                    soup.move_to(x, base + sign * w * n)?;
                }
            }
        }
    }
    Ok(opened.len())
}

/// The opening of each point of the incision as a fraction of the largest, `sin(pi d / T)`:
/// `d` is the point's distance along the incision's distinct edges to its nearest tip (a
/// point on one edge only) and `T` the length of those edges, so a simple incision tapers
/// by its arc length (`sin(pi s / T)`) and one traced there and back as if traced once. An
/// incision without tips (a closed loop) tapers by its arc length along the path.
fn taper(soup: &Soup, incision: &[u32], labels: &[u32]) -> Vec<f64> {
    let m = incision.len();
    let length = |j: usize| soup.at(incision[j - 1]).distance(soup.at(incision[j]));
    // The points in order of first visit, and the distinct edges between them in order of
    // first crossing (so every sum below runs in one order: the result is reproducible).
    let mut index: HashMap<u32, usize> = HashMap::new();
    let node: Vec<usize> = labels
        .iter()
        .map(|&l| {
            let k = index.len();
            *index.entry(l).or_insert(k)
        })
        .collect();
    let mut next: Vec<Vec<(usize, f64)>> = vec![Vec::new(); index.len()];
    let mut seen: HashSet<(usize, usize)> = HashSet::new();
    let mut total = 0.0;
    for j in 1..m {
        let (a, b) = (node[j - 1], node[j]);
        if a != b && seen.insert((a.min(b), a.max(b))) {
            let len = length(j);
            next[a].push((b, len));
            next[b].push((a, len));
            total += len;
        }
    }
    let tips: Vec<usize> = (0..next.len()).filter(|&k| next[k].len() == 1).collect();
    if tips.is_empty() || total <= 0.0 || total.is_nan() {
        let mut along = vec![0.0; m];
        for j in 1..m {
            along[j] = along[j - 1] + length(j);
        }
        let total = along[m - 1];
        return along
            .iter()
            .map(|&s| {
                if total > 0.0 {
                    (PI * s / total).sin()
                } else {
                    0.0
                }
            })
            .collect();
    }
    // Dijkstra from every tip at once over the distinct edges (a few hundred points). The
    // distances are finite and not negative, so their bits order as they do.
    let mut dist = vec![f64::INFINITY; next.len()];
    let mut queue = BinaryHeap::new();
    for &t in &tips {
        dist[t] = 0.0;
        queue.push(Reverse((0.0f64.to_bits(), t)));
    }
    while let Some(Reverse((bits, k))) = queue.pop() {
        let d = f64::from_bits(bits);
        if d > dist[k] {
            continue;
        }
        for &(to, len) in &next[k] {
            if d + len < dist[to] {
                dist[to] = d + len;
                queue.push(Reverse(((d + len).to_bits(), to)));
            }
        }
    }
    // The path is connected, so every point is reached; were one not, it would stay shut.
    node.iter()
        .map(|&k| match dist[k] {
            d if d.is_finite() => (PI * d.min(0.5 * total) / total).sin(),
            _ => 0.0,
        })
        .collect()
}

/// The faces around label `l` on the left of the incision (the one holding the edge `l ->
/// next` first) and those on its right; `None` when nothing lies on the right (the incision
/// runs along the surface's boundary there) or no face holds `l -> next`.
fn sides(
    soup: &Soup,
    seams: &Seams,
    l: u32,
    next: u32,
    path: &HashSet<(u32, u32)>,
) -> Result<Option<Sides>, SurgeryError> {
    let fan = seams.fan(l);
    let copy_in = |f: u32| fan.iter().find(|x| x.0 == f).map(|x| x.1);
    let Some(&(start, _)) = fan.iter().find(|&&(f, c)| {
        let t = soup.tris[f as usize];
        (0..3).any(|k| t[k] == c && seams.label(t[(k + 1) % 3]) == next)
    }) else {
        return Ok(None);
    };
    let mut left: Vec<u32> = Vec::new();
    let mut stack = vec![start];
    while let Some(f) = stack.pop() {
        if left.contains(&f) {
            continue;
        }
        left.push(f);
        let Some(c) = copy_in(f) else { continue };
        let t = soup.tris[f as usize];
        for x in t.into_iter().filter(|&x| x != c) {
            let lx = seams.label(x);
            if path.contains(&(l.min(lx), l.max(lx))) {
                continue;
            }
            if let Some(g) = seams.across(soup, f, c, x)? {
                if copy_in(g).is_some() {
                    stack.push(g);
                }
            }
        }
    }
    let right: Vec<u32> = fan
        .iter()
        .map(|x| x.0)
        .filter(|f| !left.contains(f))
        .collect();
    Ok((!right.is_empty()).then_some((left, right)))
}

/// Give the `right` faces around label `l` their own vertices, labelled `lip`: a copy of each
/// vertex of `l` that also has faces on the `left`, the vertex itself otherwise. The two sides
/// stop being neighbours. Returns the vertices of each lip.
fn divide(
    soup: &mut Soup,
    seams: &mut Seams,
    l: u32,
    left: &[u32],
    right: &[u32],
    lip: u32,
) -> Result<(Vec<u32>, Vec<u32>), SurgeryError> {
    let (mut near, mut far) = (Vec::new(), Vec::new());
    for c in seams.copies(l) {
        let on = |faces: &[u32]| faces.iter().any(|&f| soup.tris[f as usize].contains(&c));
        match (on(left), on(right)) {
            (true, true) => {
                let d = soup.copy_vertex(c);
                seams.push(d, d);
                for &f in right {
                    seams.replace(soup, f, c, d);
                }
                near.push(c);
                far.push(d);
            }
            (false, true) => far.push(c),
            _ => near.push(c),
        }
    }
    for &f in right {
        soup.mark(f);
        for g in soup.nb[f as usize] {
            if left.contains(&g) {
                soup.unlink(f, g);
            }
        }
    }
    seams.divide(l, near.clone(), far.clone(), lip);
    Ok((near, far))
}

/// The direction the left lip of incision vertex `v` moves: the normal of the step plane
/// nearest to it, turned towards the left face `left`.
fn opening_direction(soup: &Soup, planes: &[(DVec3, DVec3)], v: u32, left: u32) -> DVec3 {
    let p = soup.at(v);
    let off = |pl: &(DVec3, DVec3)| pl.0.dot(p - pl.1).abs();
    let Some(step) = planes.iter().min_by(|a, b| off(a).total_cmp(&off(b))) else {
        return DVec3::ZERO;
    };
    let lt = soup.tris[left as usize].map(|x| soup.at(x));
    let centre = (lt[0] + lt[1] + lt[2]) / 3.0;
    if step.0.dot(centre - p) >= 0.0 {
        step.0
    } else {
        -step.0
    }
}
