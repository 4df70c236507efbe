//! Following the swept blade's plane over the skin from one scalpel point to the next
//! (Algorithm 2, steps 5-6). The plane meets the surface in curves; the one through the first
//! point `S_i` is traced both ways, face by face, across as many faces as it crosses and across
//! UV seams (by the labels of [`Seams`]), until it reaches the next point `S_{i+1}`, closes on
//! itself, or leaves the surface. Of the arcs that reach `S_{i+1}`, the one that stays nearest
//! to the swept blade (the hull of the two blades) is taken, the shorter on a tie; only then
//! is the mesh edited: each edge the arc crosses is split at the crossing (with its seam twin),
//! so the incision becomes a chain of mesh edges.
//!
//! Vertices are classified once per step, as the cut classifies them: a vertex whose crossing
//! edge would be cut within [`super::TearOptions::snap`] of it counts as on the plane (taken
//! as an incision vertex, not moved), so no slivers appear.

use super::super::nearest::distance_to_hull;
use super::super::soup::Soup;
use super::super::SurgeryError;
use super::seams::Seams;
use super::Scalpel;
use crate::mesh::numbers::{short_number, short_point};
use glam::DVec3;
use std::collections::HashMap;

/// One step of a tear: from scalpel point `from` to `to` in the plane `(normal, point)`.
pub(super) struct Step {
    /// The step's number (from 0).
    pub index: usize,
    /// The scalpel point the incision leaves from.
    pub from: u32,
    /// The scalpel point it goes to.
    pub to: u32,
    /// The plane's unit normal.
    pub normal: DVec3,
    /// A point of the plane.
    pub point: DVec3,
    /// The blades at the step's two ends.
    pub blades: [Scalpel; 2],
    /// The snap fraction.
    pub snap: f64,
    /// The model's bounding-box diagonal (scale of tolerances).
    pub diagonal: f64,
}

/// How the trace came to a vertex (so that it does not turn back).
#[derive(Clone, Copy, Debug)]
enum Came {
    /// It starts there.
    Start,
    /// Along an edge from the vertex with this label.
    From(u32),
    /// Across this face.
    Through(u32),
}

/// The trace's next move.
#[derive(Clone, Copy, Debug)]
enum Move {
    /// To a vertex on the plane.
    Vertex { v: u32, came: Came },
    /// Across face `f`, leaving it through its edge `a b` at `a + t (b - a)`.
    Cross { f: u32, a: u32, b: u32, t: f64 },
}

/// A point of the incision: a vertex, or the crossing of the soup edge `a b` at `t`.
#[derive(Clone, Copy, Debug)]
enum Event {
    At(u32),
    Cross { a: u32, b: u32, t: f64 },
}

/// How a trace ended.
#[derive(Clone, Copy, Debug, PartialEq)]
enum End {
    Reached,
    Closed,
    Boundary,
    Stuck,
    TooLong,
}

/// The curve followed one way from the first scalpel point.
struct Trace {
    events: Vec<Event>,
    points: Vec<DVec3>,
    end: End,
}

/// Signed distances to the step's plane, by label, snapped as the module says.
struct Level {
    normal: DVec3,
    point: DVec3,
    snap: f64,
    tiny: f64,
    /// The two scalpel points: on the plane by definition.
    forced: [u32; 2],
    cache: HashMap<u32, f64>,
}

impl Level {
    fn new(step: &Step, seams: &Seams) -> Level {
        Level {
            normal: step.normal,
            point: step.point,
            snap: step.snap,
            tiny: 1e-12 * step.diagonal,
            forced: [seams.label(step.from), seams.label(step.to)],
            cache: HashMap::new(),
        }
    }

    /// The signed distance of the label's own vertex.
    fn raw(&self, soup: &Soup, l: u32) -> f64 {
        self.normal.dot(soup.at(l) - self.point)
    }

    /// Vertex `v`'s signed distance, zero when it is snapped onto the plane.
    fn value(&mut self, soup: &Soup, seams: &Seams, v: u32) -> Result<f64, SurgeryError> {
        let l = seams.label(v);
        if self.forced.contains(&l) {
            return Ok(0.0);
        }
        if let Some(&s) = self.cache.get(&l) {
            return Ok(s);
        }
        let r = self.raw(soup, l);
        let mut s = if r.abs() <= self.tiny { 0.0 } else { r };
        if s != 0.0 {
            'fan: for (f, _) in seams.fan(l) {
                for x in soup.tris[f as usize] {
                    let rx = self.raw(soup, seams.label(x));
                    if r * rx < 0.0 && r.abs() / (r.abs() + rx.abs()) < self.snap {
                        s = 0.0;
                        break 'fan;
                    }
                }
            }
        }
        self.cache.insert(l, s);
        Ok(s)
    }
}

/// Follow step `step`'s plane from its first scalpel point to its second, splitting the edges
/// it crosses; returns the incision's vertices (the two scalpel points included).
///
/// # Errors
/// [`SurgeryError::BadTool`] when the curve through the first point does not reach the second
/// (it says where the curve goes and how near it comes); [`SurgeryError::Broken`] on
/// inconsistent bookkeeping; [`SurgeryError::BadMesh`] when a new vertex cannot be mapped back
/// to the rest pose.
pub(super) fn follow(
    soup: &mut Soup,
    seams: &mut Seams,
    step: &Step,
) -> Result<Vec<u32>, SurgeryError> {
    let mut level = Level::new(step, seams);
    let starts = moves(soup, seams, &mut level, step.from, Came::Start)?;
    let (mut reached, mut failed) = (Vec::new(), Vec::new());
    for first in starts {
        let tr = trace(soup, seams, &mut level, step, first)?;
        if tr.end == End::Reached {
            reached.push(tr);
        } else {
            failed.push(tr);
        }
    }
    match choose(reached, step) {
        Some(tr) => apply(soup, seams, &tr),
        None => Err(not_joined(soup, step, &failed)),
    }
}

/// The moves from vertex `v` along the plane (not back the way the trace `came`).
fn moves(
    soup: &Soup,
    seams: &Seams,
    level: &mut Level,
    v: u32,
    came: Came,
) -> Result<Vec<Move>, SurgeryError> {
    let l = seams.label(v);
    let mut out: Vec<Move> = Vec::new();
    for (f, c) in seams.fan(l) {
        let t = soup.tris[f as usize];
        let k = soup.corner(f, c)?;
        let (a, b) = (t[(k + 1) % 3], t[(k + 2) % 3]);
        let (sa, sb) = (level.value(soup, seams, a)?, level.value(soup, seams, b)?);
        for (x, sx) in [(a, sa), (b, sb)] {
            let lx = seams.label(x);
            let back = matches!(came, Came::From(u) if u == lx);
            let known = out
                .iter()
                .any(|m| matches!(m, Move::Vertex { v, .. } if seams.label(*v) == lx));
            if sx == 0.0 && !back && !known {
                out.push(Move::Vertex {
                    v: x,
                    came: Came::From(l),
                });
            }
        }
        if sa * sb < 0.0 && !matches!(came, Came::Through(g) if g == f) {
            out.push(Move::Cross {
                f,
                a,
                b,
                t: sa / (sa - sb),
            });
        }
    }
    Ok(out)
}

/// Trace the curve from the first scalpel point, starting with `first`, until it reaches the
/// second point, comes back, leaves the surface or runs longer than the mesh allows.
fn trace(
    soup: &Soup,
    seams: &Seams,
    level: &mut Level,
    step: &Step,
    first: Move,
) -> Result<Trace, SurgeryError> {
    let mut tr = Trace {
        events: vec![Event::At(step.from)],
        points: vec![soup.at(step.from)],
        end: End::TooLong,
    };
    let (from, to) = (seams.label(step.from), seams.label(step.to));
    let mut next = first;
    for _ in 0..4 * soup.tris.len() + 16 {
        match next {
            Move::Vertex { v, came } => {
                tr.events.push(Event::At(v));
                tr.points.push(soup.at(v));
                let l = seams.label(v);
                if l == to || l == from {
                    tr.end = if l == to { End::Reached } else { End::Closed };
                    return Ok(tr);
                }
                let options = moves(soup, seams, level, v, came)?;
                let Some(m) = straightest(soup, &tr.points, options) else {
                    tr.end = End::Stuck;
                    return Ok(tr);
                };
                next = m;
            }
            Move::Cross { f, a, b, t } => {
                tr.events.push(Event::Cross { a, b, t });
                tr.points.push(soup.at(a).lerp(soup.at(b), t));
                let Some(g) = seams.across(soup, f, a, b)? else {
                    tr.end = End::Boundary;
                    return Ok(tr);
                };
                next = through(soup, seams, level, g, a, b)?;
            }
        }
    }
    Ok(tr)
}

/// The move across face `g`, entered through its edge `a b` (by labels).
fn through(
    soup: &Soup,
    seams: &Seams,
    level: &mut Level,
    g: u32,
    a: u32,
    b: u32,
) -> Result<Move, SurgeryError> {
    let t = soup.tris[g as usize];
    let (la, lb) = (seams.label(a), seams.label(b));
    let Some(k) = (0..3).find(|&i| ![la, lb].contains(&seams.label(t[i]))) else {
        return Err(SurgeryError::Broken(format!(
            "face {g} {t:?} across the edge {a} {b} holds both its ends and no third"
        )));
    };
    let c = t[k];
    let sc = level.value(soup, seams, c)?;
    if sc == 0.0 {
        return Ok(Move::Vertex {
            v: c,
            came: Came::Through(g),
        });
    }
    for x in [t[(k + 1) % 3], t[(k + 2) % 3]] {
        let sx = level.value(soup, seams, x)?;
        if sx * sc < 0.0 {
            return Ok(Move::Cross {
                f: g,
                a: x,
                b: c,
                t: sx / (sx - sc),
            });
        }
    }
    Err(SurgeryError::Broken(format!(
        "the plane enters face {g} {t:?} through the edge {a} {b} but does not leave it"
    )))
}

/// Of several ways on from the trace's last point, the one that turns least (where the
/// surface only touches the plane the curve branches).
fn straightest(soup: &Soup, points: &[DVec3], options: Vec<Move>) -> Option<Move> {
    let n = points.len();
    let here = points[n - 1];
    let dir = (here - points[n.saturating_sub(2)]).normalize_or_zero();
    let turn = |m: &Move| {
        let p = match *m {
            Move::Vertex { v, .. } => soup.at(v),
            Move::Cross { a, b, t, .. } => soup.at(a).lerp(soup.at(b), t),
        };
        dir.dot((p - here).normalize_or_zero())
    };
    options
        .into_iter()
        .max_by(|p, q| turn(p).total_cmp(&turn(q)))
}

/// Of the arcs that reach the second point, the one that strays least from the swept blade
/// (the hull of the two blades), the shorter when they stray alike.
fn choose(reached: Vec<Trace>, step: &Step) -> Option<Trace> {
    let [b0, b1] = step.blades;
    let hull = [b0.a, b0.b, b1.a, b1.b];
    let tol = 1e-9 * step.diagonal;
    reached
        .into_iter()
        .map(|tr| {
            let stray = tr
                .points
                .iter()
                .map(|&p| distance_to_hull(p, &hull))
                .fold(0.0, f64::max);
            let length: f64 = tr.points.windows(2).map(|w| w[0].distance(w[1])).sum();
            (stray, length, tr)
        })
        .min_by(|x, y| {
            if (x.0 - y.0).abs() > tol {
                x.0.total_cmp(&y.0)
            } else {
                x.1.total_cmp(&y.1)
            }
        })
        .map(|x| x.2)
}

/// Make the trace's points mesh vertices, in order.
fn apply(soup: &mut Soup, seams: &mut Seams, tr: &Trace) -> Result<Vec<u32>, SurgeryError> {
    tr.events
        .iter()
        .map(|e| match *e {
            Event::At(v) => Ok(v),
            Event::Cross { a, b, t } => seams.split_at(soup, a, b, t),
        })
        .collect()
}

/// The error for a step whose scalpel points the curve does not join: where each way from
/// the first point went, and how near the curve comes to the second.
fn not_joined(soup: &Soup, step: &Step, failed: &[Trace]) -> SurgeryError {
    let (i, s, t) = (step.index, soup.at(step.from), soup.at(step.to));
    let blade = step.blades[1];
    let ways: Vec<String> = failed
        .iter()
        .map(|tr| {
            let last = tr.points[tr.points.len() - 1];
            match tr.end {
                End::Closed => format!("closes on itself after {} points", tr.points.len() - 1),
                End::Boundary => format!("reaches the surface's boundary at {}", short_point(last)),
                End::Stuck => format!(
                    "ends at {}, where the plane only touches the surface",
                    short_point(last)
                ),
                End::TooLong | End::Reached => format!("runs on for {} points", tr.points.len()),
            }
        })
        .collect();
    let ways = if ways.is_empty() {
        "the plane only touches the surface there".to_string()
    } else {
        format!(
            "followed from there, the curve {}",
            ways.join("; the other way it ")
        )
    };
    let nearest = failed
        .iter()
        .flat_map(|tr| tr.points.iter().copied())
        .min_by(|x, y| x.distance(t).total_cmp(&y.distance(t)));
    let gap = nearest.map_or(String::new(), |q| {
        format!(
            "; it passes {} from scalpel point {} at best (nearest curve point {})",
            short_number(q.distance(t)),
            i + 1,
            short_point(q)
        )
    });
    SurgeryError::BadTool(format!(
        "step {i}: the plane through scalpel point {i} at {} and blade {} (from {} to {}) meets \
         the surface in a curve that does not join scalpel point {i} to scalpel point {} at {}: \
         {ways}{gap}; move blade {} or add a scalpel position between",
        short_point(s),
        i + 1,
        short_point(blade.a),
        short_point(blade.b),
        i + 1,
        short_point(t),
        i + 1,
    ))
}
