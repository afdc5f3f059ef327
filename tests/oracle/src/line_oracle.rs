//! Exact oracle for lines against quadrics: the polynomial in `t` with
//! exact dyadic coefficients (every finite f64 is `m * 2^e`, and sums and
//! products of dyadics are dyadic), its exact root count, and its roots
//! rounded correctly to f64 by bisection on exact signs.

use super::oracle::exact_parts;
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// `m * 2^e`, exactly.
#[derive(Clone, Debug)]
pub struct Dyadic {
    m: BigInt,
    e: i64,
}

impl Dyadic {
    pub fn from_f64(v: f64) -> Dyadic {
        let (m, e) = exact_parts(v);
        Dyadic { m, e: e as i64 }
    }

    pub fn int(v: i64) -> Dyadic {
        Dyadic {
            m: BigInt::from(v),
            e: 0,
        }
    }

    pub fn add(&self, o: &Dyadic) -> Dyadic {
        let e = self.e.min(o.e);
        Dyadic {
            m: (&self.m << (self.e - e) as usize) + (&o.m << (o.e - e) as usize),
            e,
        }
    }

    pub fn sub(&self, o: &Dyadic) -> Dyadic {
        self.add(&o.neg())
    }

    pub fn neg(&self) -> Dyadic {
        Dyadic {
            m: -&self.m,
            e: self.e,
        }
    }

    pub fn mul(&self, o: &Dyadic) -> Dyadic {
        Dyadic {
            m: &self.m * &o.m,
            e: self.e + o.e,
        }
    }

    pub fn half(&self) -> Dyadic {
        Dyadic {
            m: self.m.clone(),
            e: self.e - 1,
        }
    }

    pub fn sign(&self) -> i8 {
        if self.m.is_zero() {
            0
        } else if self.m.is_positive() {
            1
        } else {
            -1
        }
    }
}

/// A vector of dyadics.
pub type V3 = [Dyadic; 3];

pub fn v3(p: [f64; 3]) -> V3 {
    p.map(Dyadic::from_f64)
}

pub fn sub3(a: &V3, b: &V3) -> V3 {
    core::array::from_fn(|k| a[k].sub(&b[k]))
}

pub fn dot3(a: &V3, b: &V3) -> Dyadic {
    a[0].mul(&b[0]).add(&a[1].mul(&b[1])).add(&a[2].mul(&b[2]))
}

pub fn cross3(a: &V3, b: &V3) -> V3 {
    core::array::from_fn(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        a[i].mul(&b[j]).sub(&a[j].mul(&b[i]))
    })
}

/// `a t^2 + b t + c`, exactly.
#[derive(Clone, Debug)]
pub struct Quadratic {
    pub a: Dyadic,
    pub b: Dyadic,
    pub c: Dyadic,
}

/// The exact answer for a line: the number of distinct real roots (`None`
/// for every `t`) and the roots rounded correctly, ascending.
#[derive(Clone, Debug, PartialEq)]
pub struct LineAnswer {
    pub count: Option<usize>,
    pub roots: Vec<f64>,
}

/// How far beyond f64::MAX, in ulps of it, a root still comes out as
/// +-f64::MAX (see [`Quadratic::answer`]).
pub const SATURATED_ULPS: i64 = 16;

impl LineAnswer {
    /// What a cast in `[min, max]` whose roots are within `ulps` units of
    /// rounding must return, by the crate's policy (`Interval::admits`: a
    /// hit only at a finite t): `Some(Some(w))` the first root in the range
    /// (correctly rounded), `Some(None)` no hit (no root in the range, or
    /// only roots so far beyond f64's range that they come out infinite),
    /// `None` where either is right (the first root in the range within
    /// `2 ulps` units of f64::MAX, or saturated to it, where the cast's
    /// rounding may or may not overflow). For a finite root count.
    pub fn first_admitted(&self, min: f64, max: f64, ulps: u32) -> Option<Option<f64>> {
        assert!(2 * i64::from(ulps) <= SATURATED_ULPS);
        let band = f64::MAX * (1.0 - 2.0 * f64::from(ulps) * f64::EPSILON);
        for &w in &self.roots {
            if !(min <= w && w <= max) || w.is_infinite() {
                continue;
            }
            return (w.abs() < band).then_some(Some(w));
        }
        Some(None)
    }
}

/// Order-preserving map from finite f64 to integers.
pub fn ordered(t: f64) -> i64 {
    let bits = t.to_bits() as i64;
    if bits < 0 { i64::MIN - bits } else { bits }
}

fn from_ordered(k: i64) -> f64 {
    f64::from_bits((if k < 0 { i64::MIN - k } else { k }) as u64)
}

/// How many ulps apart two finite values are.
pub fn ulps_between(x: f64, y: f64) -> u64 {
    ordered(x).abs_diff(ordered(y))
}

impl Quadratic {
    pub fn sphere(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64) -> Quadratic {
        let (d, w) = (v3(d), sub3(&v3(o), &v3(c)));
        let r = Dyadic::from_f64(r);
        Quadratic {
            a: dot3(&d, &d),
            b: dot3(&w, &d).mul(&Dyadic::int(2)),
            c: dot3(&w, &w).sub(&r.mul(&r)),
        }
    }

    /// `|(o + t d - p) x a|^2 - r^2 |a|^2`.
    pub fn cylinder(o: [f64; 3], d: [f64; 3], p: [f64; 3], a: [f64; 3], r: f64) -> Quadratic {
        let a = v3(a);
        let u = cross3(&sub3(&v3(o), &v3(p)), &a);
        let v = cross3(&v3(d), &a);
        let r = Dyadic::from_f64(r);
        Quadratic {
            a: dot3(&v, &v),
            b: dot3(&u, &v).mul(&Dyadic::int(2)),
            c: dot3(&u, &u).sub(&r.mul(&r).mul(&dot3(&a, &a))),
        }
    }

    /// `|a|^2 |w x a|^2 - r^2 (w . a)^2`, `w = o + t d - apex`.
    pub fn cone(o: [f64; 3], d: [f64; 3], apex: [f64; 3], a: [f64; 3], r: f64) -> Quadratic {
        let (a, d) = (v3(a), v3(d));
        let w = sub3(&v3(o), &v3(apex));
        let s = dot3(&a, &a);
        let rr = Dyadic::from_f64(r).mul(&Dyadic::from_f64(r));
        let (u, v) = (cross3(&w, &a), cross3(&d, &a));
        let (p, q) = (dot3(&w, &a), dot3(&d, &a));
        Quadratic {
            a: s.mul(&dot3(&v, &v)).sub(&rr.mul(&q).mul(&q)),
            b: s.mul(&dot3(&u, &v))
                .sub(&rr.mul(&p).mul(&q))
                .mul(&Dyadic::int(2)),
            c: s.mul(&dot3(&u, &u)).sub(&rr.mul(&p).mul(&p)),
        }
    }

    /// The quadric `[A..J]` along `o + t d`.
    pub fn quadric(o: [f64; 3], d: [f64; 3], k: [f64; 10]) -> Quadratic {
        let k = k.map(Dyadic::from_f64);
        // Q(x) with x = o + t d, expanded by evaluating the quadratic form
        // at (o, 1) and (d, 0) in homogeneous coordinates.
        let m = |i: usize, j: usize| -> Dyadic {
            // Entries of 2Q, see the crate's doubled_matrix.
            let two = Dyadic::int(2);
            match (i.min(j), i.max(j)) {
                (0, 0) => k[0].mul(&two),
                (1, 1) => k[1].mul(&two),
                (2, 2) => k[2].mul(&two),
                (3, 3) => k[9].mul(&two),
                (0, 1) => k[3].clone(),
                (0, 2) => k[4].clone(),
                (1, 2) => k[5].clone(),
                (0, 3) => k[6].clone(),
                (1, 3) => k[7].clone(),
                _ => k[8].clone(),
            }
        };
        let x: [Dyadic; 4] = [
            Dyadic::from_f64(o[0]),
            Dyadic::from_f64(o[1]),
            Dyadic::from_f64(o[2]),
            Dyadic::int(1),
        ];
        let y: [Dyadic; 4] = [
            Dyadic::from_f64(d[0]),
            Dyadic::from_f64(d[1]),
            Dyadic::from_f64(d[2]),
            Dyadic::int(0),
        ];
        let form = |u: &[Dyadic; 4], v: &[Dyadic; 4]| {
            let mut s = Dyadic::int(0);
            for (i, ui) in u.iter().enumerate() {
                for (j, vj) in v.iter().enumerate() {
                    s = s.add(&ui.mul(&m(i, j)).mul(vj));
                }
            }
            s
        };
        // 2 Q(o + t d) = A t^2 + 2 B t + C; halve it back.
        Quadratic {
            a: form(&y, &y).half(),
            b: form(&y, &x),
            c: form(&x, &x).half(),
        }
    }

    pub fn sign_at(&self, t: &Dyadic) -> i8 {
        self.a.mul(t).add(&self.b).mul(t).add(&self.c).sign()
    }

    fn slope_sign_at(&self, t: &Dyadic) -> i8 {
        self.a.mul(t).mul(&Dyadic::int(2)).add(&self.b).sign()
    }

    pub fn discriminant_sign(&self) -> i8 {
        self.b
            .mul(&self.b)
            .sub(&self.a.mul(&self.c).mul(&Dyadic::int(4)))
            .sign()
    }

    /// The exact number of distinct real roots, `None` when identically 0.
    pub fn count(&self) -> Option<usize> {
        if self.a.sign() == 0 {
            return if self.b.sign() != 0 {
                Some(1)
            } else if self.c.sign() == 0 {
                None
            } else {
                Some(0)
            };
        }
        Some(match self.discriminant_sign() {
            1 => 2,
            0 => 1,
            _ => 0,
        })
    }

    /// The count and the correctly rounded roots (ties to even), found by
    /// bisection over the doubles on the monotone branch each root lies on.
    /// The branches meet at the exact vertex `v = -b / 2a`, which is
    /// compared exactly (by the sign of the slope `2 a t + b`) with every
    /// point the bisection evaluates: two roots that are adjacent doubles,
    /// or within an ulp of each other, are told apart however `v` rounds.
    /// A root beyond f64's range comes out as +-f64::MAX within
    /// [`SATURATED_ULPS`] ulps of it, and as an infinity of its sign (as
    /// the crate's casts return it) beyond.
    pub fn answer(&self) -> LineAnswer {
        let count = self.count();
        let roots = match count {
            Some(n) => (0..n)
                .map(|i| self.round_change(|t| self.step(count, i, t)))
                .collect(),
            None => vec![],
        };
        LineAnswer { count, roots }
    }

    /// The step function of the `index`-th distinct real root, ascending,
    /// given the finite `count` ([`Quadratic::count`]): -1 below the root,
    /// 0 at it, +1 above.
    fn step(&self, count: Option<usize>, index: usize, t: &Dyadic) -> i8 {
        let s = self.a.sign();
        // The slope's sign times a's: the side of the vertex t lies on.
        let side = |t: &Dyadic| s * self.slope_sign_at(t);
        match (count, index) {
            (Some(1), 0) if s == 0 => self.b.sign() * self.sign_at(t),
            // A double root: the vertex itself.
            (Some(1), 0) => side(t),
            // Left of the lower root p has a's sign, between the roots the
            // opposite one; each root's step function is constant on the
            // far side of the vertex.
            (Some(2), 0) => {
                if side(t) >= 0 {
                    1
                } else {
                    -s * self.sign_at(t)
                }
            }
            (Some(2), 1) => {
                if side(t) <= 0 {
                    -1
                } else {
                    s * self.sign_at(t)
                }
            }
            _ => panic!("no root {index} of {self:?}"),
        }
    }

    /// Whether the `index`-th distinct real root (ascending) lies in
    /// `[t - error, t + error]`, decided exactly (the ends as exact sums):
    /// the check of a value that comes with a certified bound. An infinite
    /// or NaN `error` bounds nothing and counts as holding only when
    /// infinite.
    pub fn root_within(&self, index: usize, t: f64, error: f64) -> bool {
        if error == f64::INFINITY {
            return true;
        }
        if !(t.is_finite() && error.is_finite() && error >= 0.0) {
            return false;
        }
        let count = self.count();
        let (t, e) = (Dyadic::from_f64(t), Dyadic::from_f64(error));
        self.step(count, index, &t.sub(&e)) <= 0 && self.step(count, index, &t.add(&e)) >= 0
    }

    /// The double nearest the point where the monotone step function `f`
    /// (-1 below, +1 above, 0 at) changes. Beyond +-f64::MAX: +-f64::MAX
    /// (saturated) within [`SATURATED_ULPS`] ulps of it, where a cast's
    /// rounded root may still be finite; an infinity of its sign beyond
    /// that, where no root within a few ulps is finite.
    fn round_change(&self, f: impl Fn(&Dyadic) -> i8) -> f64 {
        // (2^53 - 1 + SATURATED_ULPS) 2^971, exactly.
        let edge = Dyadic::from_f64(f64::MAX)
            .add(&Dyadic::from_f64(2f64.powi(971)).mul(&Dyadic::int(SATURATED_ULPS)));
        if f(&Dyadic::from_f64(f64::MAX)) < 0 {
            return if f(&edge) < 0 {
                f64::INFINITY
            } else {
                f64::MAX
            };
        }
        if f(&Dyadic::from_f64(-f64::MAX)) > 0 {
            return if f(&edge.neg()) > 0 {
                f64::NEG_INFINITY
            } else {
                -f64::MAX
            };
        }
        self.bisect(f, ordered(-f64::MAX), ordered(f64::MAX))
    }

    /// The double nearest the point where the monotone step function
    /// `f` (-1 below, +1 above, 0 at) changes, within `[lo, hi]`.
    fn bisect(&self, f: impl Fn(&Dyadic) -> i8, mut lo: i64, mut hi: i64) -> f64 {
        let at = |k: i64| f(&Dyadic::from_f64(from_ordered(k)));
        if at(lo) >= 0 {
            return from_ordered(lo);
        }
        if at(hi) <= 0 {
            return from_ordered(hi);
        }
        // Invariant: f(lo) < 0 < f(hi).
        while (hi as i128) - (lo as i128) > 1 {
            let mid = ((lo as i128 + hi as i128) / 2) as i64;
            match at(mid) {
                0 => return from_ordered(mid),
                s if s < 0 => lo = mid,
                _ => hi = mid,
            }
        }
        let (x, y) = (from_ordered(lo), from_ordered(hi));
        let midpoint = Dyadic::from_f64(x).add(&Dyadic::from_f64(y)).half();
        match f(&midpoint) {
            s if s < 0 => y,
            s if s > 0 => x,
            _ => {
                if x.to_bits() & 1 == 0 {
                    x
                } else {
                    y
                }
            }
        }
    }
}
