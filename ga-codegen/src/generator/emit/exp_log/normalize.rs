//! The emitted closed-form normalisation and square root of an even versor
//! (`impl EvenVersor`); see [`crate::generator::emit::exp_log`].

use super::decompose::{classify, span};
use super::negative_squares;
use super::{build, grade_part, Ctx};
use crate::generator::emit::render::{doc, ident};
use crate::generator::emit::Gen;
use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{Poly, Product, SymMv, Var};
use crate::runtime::blade::{grade, Bitmap};
use crate::runtime::rational::Rational;
use proc_macro2::TokenStream;
use quote::quote;

impl Gen<'_> {
    /// `impl EvenVersor for V` when `(a + W) V` stays in `V` for the grade-4 part `W` of
    /// `V ~V`.
    /// `pairs` are [`Gen::exp_pairs`] (a screw's root beyond a half turn calls `exp`).
    pub(crate) fn root_impl(&mut self, vt: &TypeDef, pairs: &[(usize, usize)]) -> TokenStream {
        let s = self.s.clone();
        let mut cx = Ctx::new(vt, s.clone());
        let v0 = SymMv::of_type(vt, 0);
        let (v_stmt, v) = cx.local("v", &v0, Some(&quote!(k)));
        let Some(body) = self.normalize_body(vt, &mut cx, &v) else {
            return TokenStream::new();
        };
        let vn = ident(&vt.name);
        let largest = largest_coefficient(vt);
        let dn = self.normalize_doc(vt);
        let turn = self.turn_root(vt, pairs);
        let dr = root_doc(turn.is_some());
        let item = turn.as_ref().map(|t| t.item.clone());
        let root = self.root_body(vt, turn.map(|t| t.guard));
        quote! {
            #item
            impl EvenVersor for #vn {
                #dn
                #[inline]
                #[allow(unused_variables, clippy::neg_multiply, clippy::double_parens)]
                fn normalize(self) -> Self {
                    let k: #s = 1.0 / #largest;
                    #v_stmt
                    #body
                }
                #dr
                #[inline]
                #[allow(unused_variables, clippy::neg_multiply, clippy::double_parens)]
                fn sqrt(self) -> Self {
                    #root
                }
            }
        }
    }

    /// The body of `normalize` after the statement of the local `v` (`self` over its largest
    /// coefficient, in `cx`): `v / sqrt(n0)` when `v ~v` is the scalar `n0`, else
    /// `(a - n4) v / sqrt(2 a N)`; `None` when `(a - n4) v` leaves the type.
    fn normalize_body(&mut self, vt: &TypeDef, cx: &mut Ctx<'_>, v: &SymMv) -> Option<TokenStream> {
        let s = self.s.clone();
        let vv = self.table.product(v, &v.rev(), Product::Geometric);
        let n0 = cx.poly(&vv.get(0));
        let (n4_stmt, n4) = cx.local("n4", &grade_part(&vv, 4), None);
        if n4.0.is_empty() {
            let result = build(vt, |x| {
                v.0.contains_key(&x).then(|| {
                    let e = cx.at(v, x);
                    quote!(#e * r)
                })
            });
            return Some(quote! {
                let n0: #s = #n0;
                let r = 1.0 / n0.sqrt();
                #result
            });
        }
        // y = a - n4 as a local: [a, -n4...] on blades [0, n4 blades].
        let mut y = SymMv::default();
        let operand = 3 + cx.locals.len() as u8;
        y.0.insert(0, Poly::var(Var { operand, field: 0 }, Rational::ONE));
        for (i, b) in n4.0.keys().enumerate() {
            let var = Var {
                operand,
                field: i as u16 + 1,
            };
            y.0.insert(*b, Poly::var(var, -Rational::ONE));
        }
        cx.locals.push(ident("y"));
        // On the left: (y v)(y v)~ = y (v ~v) y = 1, as y is a function of v ~v.
        let vy = self.table.product(&y, v, Product::Geometric);
        if !vy.support().iter().all(|b| vt.blades().any(|x| x == *b)) {
            return None;
        }
        let qp = self.table.product(&n4, &n4, Product::Geometric).get(0);
        // `sqrt(n0^2 - q)` without squaring `n0`, which underflows when the rotation part is
        // tiny next to the translation; `|n0|` where `q` is identically zero (PGA and CGA
        // motors: two divisions and a square root fewer).
        let sn = if qp.is_zero() {
            quote!(let sn = n0.abs();)
        } else {
            let qn = cx.poly(&qp);
            quote! {
                let q: #s = #qn;
                let sn = if n0 != 0.0 {
                    n0.abs() * (1.0 - q / n0 / n0).max(0.0).sqrt()
                } else {
                    (-q).max(0.0).sqrt()
                };
            }
        };
        let ys = (0..n4.0.len()).map(|i| {
            let i = proc_macro2::Literal::usize_unsuffixed(i);
            quote!(n4[#i])
        });
        let m = proc_macro2::Literal::usize_unsuffixed(n4.0.len() + 1);
        let result = build(vt, |x| {
            vy.0.contains_key(&x).then(|| {
                let e = cx.at(&vy, x);
                quote!((#e) * r)
            })
        });
        Some(quote! {
            let n0: #s = #n0;
            #n4_stmt
            #sn
            let a = n0 + sn;
            let y: [#s; #m] = [a, #(#ys),*];
            // `sqrt(2 a) sn`, not `sqrt(2 a sn^2)`: `a sn^2 ~ n0^3` underflows likewise.
            let r = 1.0 / ((2.0 * a).sqrt() * sn);
            #result
        })
    }

    /// The doc of `normalize` on `vt` (with the caveats of a span whose squares may be complex).
    fn normalize_doc(&self, vt: &TypeDef) -> TokenStream {
        doc(&format!(
            "`self` divided by the square root of `self ~self`, in closed form. `x = self ~self` \
             is a scalar `n0` plus a grade-4 part `n4` with `n4 n4 = q` a scalar, so \
             `sqrt(x) = (x + sqrt(N)) / sqrt(2 (n0 + sqrt(N)))` with `N = n0^2 - q`, and \
             `self / sqrt(x) = (a - n4) self / sqrt(2 a N)` (on the left, so that the result times its reverse is `x^(-1/2) x x^(-1/2) = 1` even when `n4` does not commute with `self`), `a = n0 + sqrt(N)` (for PGA and \
             CGA motors `q = 0`: `(1 - n4/(2 n0)) self / sqrt(n0)`). `self` is first divided by \
             its largest coefficient, so huge and tiny `{}`s normalise without overflow. Not \
             finite for zero{}.",
            vt.name,
            if classify(&self.spec.metric, span(vt.blades())).is_ok_and(|k| k.complex_squares()) {
                ", nor where `N < 0` or `n0 + sqrt(N) <= 0` (with two directions of each sign \
                 `q` can be positive, and `x` then has the two halves `n0 +- sqrt(q)`: one of \
                 them negative, as for an element drifted across the null cone, leaves no real \
                 square root)"
            } else {
                ""
            }
        ))
    }

    /// The body of `sqrt`: `normalize(1 + self)`, and where `self`'s grade-4 part `u4` can
    /// square positive (two commuting rotations), the root split along `J = u4 / sqrt(u4 u4)`
    /// when `normalize(1 + self)` would cancel (see the method's doc).
    fn root_body(&mut self, vt: &TypeDef, turn: Option<Option<Poly>>) -> TokenStream {
        let split = self.split_root(vt).unwrap_or_default();
        let s = self.s.clone();
        let mut cx = Ctx::new(vt, s.clone());
        let v0 = SymMv::of_type(vt, 0);
        // A rotation with a translation, boost or dilation beyond a half turn: `exp(log / 2)`
        // the long way round (`turn_root.rs`).
        let beyond = match turn {
            Some(guard) => {
                let method = ident(super::turn_root::METHOD);
                let s0 = cx.at(&v0, 0);
                let guard = guard.map(|q| {
                    let q = cx.poly(&q);
                    quote!(&& (#q) <= 0.0)
                });
                quote! {
                    if #s0 < 0.0 #guard {
                        return EvenVersor::normalize(self).#method();
                    }
                }
            }
            None => TokenStream::new(),
        };
        // `self` over its largest coefficient, so that `|self|^2` cannot overflow.
        let (v_stmt, v) = cx.local("v", &v0, Some(&quote!(k)));
        let mut y = v.clone();
        y.0.remove(&0);
        let yy = cx.poly(&self.table.product(&y, &y.rev(), Product::Geometric).get(0));
        let s0 = cx.at(&v, 0);
        let result = build(vt, |b| {
            if b == 0 {
                Some(quote!(a))
            } else {
                v.0.contains_key(&b).then(|| cx.at(&v, b))
            }
        });
        let largest = largest_coefficient(vt);
        quote! {
            #beyond
            #split
            let k: #s = 1.0 / #largest;
            #v_stmt
            let s: #s = #s0;
            // `|v|^2 = s^2 + <y ~y>`, `y = v - s`; `|v| + s` without cancelling near `-1`.
            let yy: #s = #yy;
            let l = (s * s + yy).max(0.0).sqrt();
            let a: #s = if s >= 0.0 { l + s } else { yy / (l - s) };
            #result.normalize()
        }
    }

    /// The split root's early return (`None` where `u4 u4` is never positive or the products
    /// leave the type).
    fn split_root(&mut self, vt: &TypeDef) -> Option<TokenStream> {
        let s = self.s.clone();
        let mut cx = Ctx::new(vt, s.clone());
        let u = SymMv::of_type(vt, 0);
        let u2 = grade_part(&u, 2);
        let u4 = grade_part(&u, 4);
        if u2.0.is_empty() || u4.0.is_empty() {
            return None;
        }
        let qu = self.table.product(&u4, &u4, Product::Geometric).get(0);
        if qu.is_zero() || negative_squares(&qu) {
            return None;
        }
        let blades = u2.support();
        let nb = proc_macro2::Literal::usize_unsuffixed(blades.len());
        let j_ops = self.j_operators(&mut cx, &u4, &blades)?;
        let complex =
            classify(&self.spec.metric, span(vt.blades())).is_ok_and(|k| k.complex_squares());
        let half = half_root(&s, blades.len(), complex);
        let s0 = cx.at(&u, 0);
        let qu = cx.poly(&qu);
        let x_terms: Vec<TokenStream> = blades.iter().map(|b| cx.at(&u, *b)).collect();
        let result = build(vt, |b| match grade(b) {
            0 => Some(quote!(a)),
            2 => blades.iter().position(|x| *x == b).map(|i| {
                let i = proc_macro2::Literal::usize_unsuffixed(i);
                quote!(yp[#i] + ym[#i])
            }),
            4 => u4.0.contains_key(&b).then(|| {
                let e = cx.at(&u, b);
                quote!(bj * (#e))
            }),
            _ => None,
        });
        Some(quote! {
            let s: #s = #s0;
            let qu: #s = #qu;
            let p = qu.max(0.0).sqrt();
            // `normalize(1 + self)` loses about `(1 + s)^2 / N` (`N = (1 + s)^2 - p^2`), the
            // split about `1 / p` (through `J`): the smaller loss.
            let s1 = (1.0 + s) * (1.0 + s);
            if qu > 0.0 && s1 - qu < p * s1 {
                // P+- = (1 +- J) / 2 split `self` into two complex numbers `s +- p + X P+-`.
                let ip = 1.0 / p;
                #j_ops
                let xs: [#s; #nb] = [#(#x_terms),*];
                let xj = times_j(xs);
                #half
                let (rp, yp) = half(s + p, std::array::from_fn(|i| 0.5 * (xs[i] + xj[i])), 1.0);
                let (rm, ym) = half(s - p, std::array::from_fn(|i| 0.5 * (xs[i] - xj[i])), -1.0);
                let a = 0.5 * (rp + rm);
                let bj = 0.5 * (rp - rm) * ip;
                return #result;
            }
        })
    }

    /// The split root's closures on bivectors `x` over `blades` (`u2`'s), as arrays: `times_j`
    /// (`x J`), `j_x_j` (`J x J`), `neg_square` (`-<x x>`) and `in_half` (the part of `x` that
    /// commutes with `J` and lies in the half `P+-`), with `J = u4 / p` (`ip = 1 / p` is in
    /// scope). `None` when `x u4` leaves `blades` in grade 2.
    fn j_operators(
        &mut self,
        cx: &mut Ctx<'_>,
        u4: &SymMv,
        blades: &[Bitmap],
    ) -> Option<TokenStream> {
        let s = self.s.clone();
        let nb = proc_macro2::Literal::usize_unsuffixed(blades.len());
        // `x u4 = p x J` for a bivector `x` on `u2`'s blades (its grade-2 part: `x` commutes
        // with `J` for the parts of a versor).
        let x = cx.declare(ident("x"), blades.iter().copied());
        let xj = self.table.product(&x, u4, Product::Geometric);
        if !xj
            .support()
            .iter()
            .all(|b| grade(*b) != 2 || blades.contains(b))
        {
            return None;
        }
        let xj_terms: Vec<TokenStream> = blades.iter().map(|b| cx.at(&xj, *b)).collect();
        let xx = cx.poly(&self.table.product(&x, &x, Product::Geometric).get(0));
        // `J x J` times `p^2` through `t = u4 x`.
        let t = self.table.product(u4, &x, Product::Geometric);
        let t_terms: Vec<TokenStream> = t.0.values().map(|p| cx.poly(p)).collect();
        let nt = proc_macro2::Literal::usize_unsuffixed(t_terms.len());
        let t_sym = cx.declare(ident("t"), t.0.keys().copied());
        let jxj = self.table.product(&t_sym, u4, Product::Geometric);
        let jxj_terms: Vec<TokenStream> = blades.iter().map(|b| cx.at(&jxj, *b)).collect();
        Some(quote! {
            let times_j = |x: [#s; #nb]| -> [#s; #nb] { [#((#xj_terms) * ip),*] };
            let j_x_j = |x: [#s; #nb]| -> [#s; #nb] {
                let t: [#s; #nt] = [#(#t_terms),*];
                [#((#jxj_terms) * (ip * ip)),*]
            };
            let neg_square = |x: [#s; #nb]| -> #s { -2.0 * (#xx) };
            // Twice the part of `x` that commutes with `J` (`(x + J x J) / 2`) and lies in
            // the half `P+-`, up to a positive factor.
            let in_half = |x: [#s; #nb], sign: #s| -> [#s; #nb] {
                let jxj = j_x_j(x);
                let c: [#s; #nb] = std::array::from_fn(|i| x[i] + jxj[i]);
                let cj = times_j(c);
                std::array::from_fn(|i| c[i] + sign * cj[i])
            };
        })
    }
}

/// The split root's `half` closure (scalar type `s`, `nb` bivector fields): the root of one
/// half `r + y` (a complex number, or a split-complex one where the span's squares may be
/// complex: `complex`), in the stable form, and near `-1` through its unit imaginary part
/// projected on the half again.
fn half_root(s: &TokenStream, nb: usize, complex: bool) -> TokenStream {
    let nb = proc_macro2::Literal::usize_unsuffixed(nb);
    // With two directions of each sign a half can be a split-complex number (`y y > 0`,
    // from two boosts or a complex pair of squares): its root `re + y / (2 re)` has
    // `re^2 = (r + sqrt(r^2 - y y))/2`, the elliptic formula with `m^2 = -y y` of either
    // sign.
    let m_rho = if complex {
        quote! {
            let m2 = neg_square(y);
            let m = m2.max(0.0).sqrt();
            let rho = (r * r + m2).max(0.0).sqrt();
        }
    } else {
        quote! {
            let m = neg_square(y).max(0.0).sqrt();
            let rho = (r * r + m * m).sqrt();
        }
    };
    quote! {
        let half = |r: #s, y: [#s; #nb], sign: #s| -> (#s, [#s; #nb]) {
            #m_rho
            if r >= 0.0 {
                let re = (0.5 * (rho + r)).sqrt();
                let c = 0.5 / re;
                (re, y.map(|v| c * v))
            } else {
                // Near -1: the imaginary unit `y / m`, projected on its half again
                // (rounding leaks into the other half and into bivectors that do not
                // commute with `J`, divided by `m`) and rescaled to unit length.
                let t = (0.5 * (rho - r)).sqrt();
                let e = y.map(|v| v / m);
                let mut f = in_half(e, sign);
                let mut n = neg_square(f);
                // `f` is 4 e for an `e` in the half; under a quarter of that, `y` was
                // rounding (on the cut at this precision) and its direction is noise.
                if n.is_nan() || n <= 4.0 {
                    // On the cut every unit imaginary of the half gives a root: take
                    // the largest part of a basis bivector in the half.
                    n = 0.0;
                    for k in 0..#nb {
                        let mut x: [#s; #nb] = [0.0; #nb];
                        x[k] = 1.0;
                        let g = in_half(x, sign);
                        let ng = neg_square(g);
                        if ng > n {
                            n = ng;
                            f = g;
                        }
                    }
                }
                let k = t / n.sqrt();
                (m / (2.0 * t), f.map(|v| k * v))
            }
        };
    }
}

/// The doc of `sqrt`; `screw`: the type has the root beyond a half turn through `exp(log / 2)`
/// (`turn_root.rs`).
fn root_doc(screw: bool) -> TokenStream {
    let screw = if screw {
        " For a rotation with a commuting part that is not one (as here: a translation along \
         its axis, a boost or a dilation) `1 + v` near `-1` is mostly that other part and \
         normalising it would cancel terms of size `1 / d`, so beyond a half turn \
         (`<self>_0 < 0`) the root is `exp(log(v) / 2)` with the logarithm read the long way \
         round, its rotation part split off as `log` does and projected on the simple \
         bivectors once more: an exact versor whose square is `v` to rounding (near the full \
         turn the rotation's axis is fixed by `v` only to `eps |other part| / d`, which moves \
         the motion by `eps |other part|`)."
    } else {
        ""
    };
    doc(&format!(
        "The square root (half the motion) of `v = self / |self|`: `normalize(1 + v)`, \
         which is `sqrt(v)` for a unit even versor because `1 + v = sqrt(v) (~sqrt(v) + \
         sqrt(v))` and the second factor is a scalar plus a grade-4 part that normalisation \
         removes. `self` is divided by its largest coefficient first, and `1 + v` is taken \
         as `|self| + <self>_0` (`|self|^2 = <self>_0^2 + <y ~y>_0`, `y` the rest of \
         `self`), which for `<self>_0 < 0` is computed as `<y ~y>_0 / (|self| - <self>_0)`: \
         near `-1` (a full turn) `1 + <self>_0` would cancel and lose about `eps / d` at a \
         distance `d`; this keeps a rotation's root to rounding of `self`'s \
         coefficients.{screw} Where the \
         grade-4 part `u4` of `self` squares to `p^2 > 0` (two commuting rotations) and \
         `N = (1 + <self>_0)^2 - p^2` is under `p (1 + <self>_0)^2` (dividing by `N` would \
         lose more than dividing by `p`), that factor is nearly a zero divisor (it is one \
         where the two angles sum to a half turn) and `normalize(1 + self)` would cancel; there the \
         root is taken in the two halves `P+- = (1 +- J) / 2`, `J = u4 / p`, separately: \
         each is a complex number `<self>_0 +- p + X P+-` (`X` the bivector part) whose root \
         is taken in the stable form (near `-1` through its unit imaginary part, projected \
         on its half and on the bivectors commuting with `J` again), so that the result \
         squares back to `self` to rounding; on that cut (to the precision), where the \
         roots form a sphere, the one through the basis bivector with the largest part in \
         the half. Not finite for zero or `-1` (a full turn has no unique half)."
    ))
}

/// `self`'s largest coefficient in absolute value (the scale `normalize` and `sqrt` divide by
/// first, so that no square of a coefficient overflows).
fn largest_coefficient(vt: &TypeDef) -> TokenStream {
    let first = ident(&vt.fields[0].name);
    let rest = vt.fields[1..].iter().map(|f| {
        let id = ident(&f.name);
        quote!(self.#id.abs())
    });
    quote!(self.#first.abs() #(.max(#rest))*)
}
