//! The emitted closed-form normalisation and square root of an even versor
//! (`impl EvenVersor`); see [`super::exp_log`].

use super::exp_log::{build, grade_part, Ctx};
use super::render::{doc, ident};
use super::Gen;
use crate::rational::Rational;
use crate::spec::TypeDef;
use crate::symbolic::{Poly, Product, SymMv, Var};
use proc_macro2::TokenStream;
use quote::quote;

impl Gen<'_> {
    /// `impl EvenVersor for V` when `(a + W) V` stays in `V` for the grade-4 part `W` of
    /// `V ~V`.
    pub(super) fn root_impl(&mut self, vt: &TypeDef) -> TokenStream {
        let s = self.s.clone();
        let mut cx = Ctx::new(vt, s.clone());
        let v0 = SymMv::of_type(vt, 0);
        let (v_stmt, v) = cx.local("v", &v0, Some(&quote!(k)));
        let vv = self.table.product(&v, &v.rev(), Product::Geometric);
        let n0 = cx.poly(&vv.get(0));
        let (n4_stmt, n4) = cx.local("n4", &grade_part(&vv, 4), None);
        let vn = ident(&vt.name);
        let body = if n4.0.is_empty() {
            let result = build(vt, |x| {
                v.0.contains_key(&x).then(|| {
                    let e = cx.at(&v, x);
                    quote!(#e * r)
                })
            });
            quote! {
                let n0: #s = #n0;
                let r = 1.0 / n0.sqrt();
                #result
            }
        } else {
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
            let vy = self.table.product(&y, &v, Product::Geometric);
            if !vy.support().iter().all(|b| vt.blades().any(|x| x == *b)) {
                return TokenStream::new();
            }
            let qn = cx.poly(&self.table.product(&n4, &n4, Product::Geometric).get(0));
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
            quote! {
                let n0: #s = #n0;
                #n4_stmt
                let sn = (n0 * n0 - (#qn)).max(0.0).sqrt();
                let a = n0 + sn;
                let y: [#s; #m] = [a, #(#ys),*];
                let r = 1.0 / (2.0 * a * sn * sn).sqrt();
                #result
            }
        };
        let scalar_field = ident(
            &vt.fields
                .iter()
                .find(|f| f.bitmap == 0)
                .expect("an even versor stores its scalar")
                .name,
        );
        let first = ident(&vt.fields[0].name);
        let maxes = vt.fields[1..].iter().map(|f| {
            let id = ident(&f.name);
            quote!(self.#id.abs())
        });
        let dn = doc(&format!(
            "`self` divided by the square root of `self ~self`, in closed form. `x = self ~self` \
             is a scalar `n0` plus a grade-4 part `n4` with `n4 n4 = q` a scalar, so \
             `sqrt(x) = (x + sqrt(N)) / sqrt(2 (n0 + sqrt(N)))` with `N = n0^2 - q`, and \
             `self / sqrt(x) = (a - n4) self / sqrt(2 a N)` (on the left, so that the result times its reverse is `x^(-1/2) x x^(-1/2) = 1` even when `n4` does not commute with `self`), `a = n0 + sqrt(N)` (for PGA and \
             CGA motors `q = 0`: `(1 - n4/(2 n0)) self / sqrt(n0)`). `self` is first divided by \
             its largest coefficient, so huge and tiny `{}`s normalise without overflow. Not \
             finite for zero.",
            vt.name
        ));
        let dr = doc(
            "The square root (half the motion): `normalize(1 + self)`, which is `sqrt(self)` for \
             a unit even versor because `1 + v = sqrt(v) (~sqrt(v) + sqrt(v))` and the second \
             factor is a scalar plus a grade-4 part that normalisation removes. Not finite for \
             `-1` (a full turn has no unique half).",
        );
        quote! {
            impl EvenVersor for #vn {
                #dn
                #[inline]
                #[allow(unused_variables, clippy::neg_multiply, clippy::double_parens)]
                fn normalize(self) -> Self {
                    let k: #s = 1.0 / self.#first.abs() #(.max(#maxes))*;
                    #v_stmt
                    #body
                }
                #dr
                #[inline]
                fn sqrt(self) -> Self {
                    let mut v = self;
                    v.#scalar_field += 1.0;
                    v.normalize()
                }
            }
        }
    }
}
