//! The exact closest triangle of a mesh to a point, by brute force: every
//! triangle's squared distance from the point as an exact fraction of big
//! integers, and the set of triangles at the least one.
//!
//! Independent of the crate's method: the closest point is found in the
//! triangle's parameters (Eberly's "Distance Between Point and Triangle
//! in 3D"): the plane's minimizer `a + s e0 + t e1` from the normal
//! equations, taken when `s >= 0`, `t >= 0`, `s + t <= 1`; otherwise the
//! least of the three edges, each a segment whose parameter is clamped to
//! `[0, 1]`. The crate instead compares seven candidates with region
//! conditions.

use crate::mesh_oracle::{Frac, V, dot, sub};
use crate::oracle::{common_integers, exact_parts};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

fn scale(a: &V, s: &BigInt) -> V {
    core::array::from_fn(|k| &a[k] * s)
}

fn add(a: &V, b: &V) -> V {
    core::array::from_fn(|k| &a[k] + &b[k])
}

/// The squared distance from `p` to the closed segment from `a` to `b`.
fn segment(p: &V, a: &V, b: &V) -> Frac {
    let e = sub(b, a);
    let ap = sub(a, p);
    let len2 = dot(&e, &e);
    if len2.is_zero() {
        return Frac::new(dot(&ap, &ap), BigInt::from(1));
    }
    // The parameter `num / len2` of the projection, clamped to [0, 1].
    let num = -dot(&ap, &e);
    let num = if num.is_negative() {
        BigInt::zero()
    } else if num > len2 {
        len2.clone()
    } else {
        num
    };
    // |len2 (a - p) + num e|^2 / len2^2.
    let v = add(&scale(&ap, &len2), &scale(&e, &num));
    Frac::new(dot(&v, &v), &len2 * &len2)
}

/// The squared distance from `p` to the closed triangle `(a, b, c)`.
fn triangle(p: &V, a: &V, b: &V, c: &V) -> Frac {
    let (e0, e1, d) = (sub(b, a), sub(c, a), sub(a, p));
    let (a00, a01, a11) = (dot(&e0, &e0), dot(&e0, &e1), dot(&e1, &e1));
    let (b0, b1) = (dot(&e0, &d), dot(&e1, &d));
    let det = &a00 * &a11 - &a01 * &a01;
    if det.is_positive() {
        let s = &a01 * &b1 - &a11 * &b0;
        let t = &a01 * &b0 - &a00 * &b1;
        if !s.is_negative() && !t.is_negative() && &s + &t <= det {
            let v = add(&add(&scale(&d, &det), &scale(&e0, &s)), &scale(&e1, &t));
            return Frac::new(dot(&v, &v), &det * &det);
        }
    }
    [segment(p, a, b), segment(p, b, c), segment(p, c, a)]
        .into_iter()
        .min()
        .expect("three edges")
}

/// The exact value of a finite `v`.
pub fn dyadic(v: f64) -> Frac {
    let (m, e) = exact_parts(v);
    if e >= 0 {
        Frac::new(m << e as usize, BigInt::from(1))
    } else {
        Frac::new(m, BigInt::from(1) << (-e) as usize)
    }
}

/// `a - b`.
pub fn difference(a: &Frac, b: &Frac) -> Frac {
    Frac::new(&a.num * &b.den - &b.num * &a.den, &a.den * &b.den)
}

/// `a * b`.
pub fn product(a: &Frac, b: &Frac) -> Frac {
    Frac::new(&a.num * &b.num, &a.den * &b.den)
}

/// The triangles of a mesh nearest to a point.
#[derive(Clone, Debug)]
pub struct Closest {
    /// The least exact squared distance, `None` when no triangle counts.
    pub least: Option<Frac>,
    /// The indices of the triangles at exactly that distance, ascending.
    pub ties: Vec<usize>,
}

/// The exact squared distance from `p` to every triangle `t` of the mesh
/// with `counts(t)`, and the triangles at the least one.
pub fn closest_triangles(
    p: [f64; 3],
    vertices: &[[f64; 3]],
    triangles: &[[u32; 3]],
    counts: impl Fn(usize) -> bool,
) -> Closest {
    let mut values = p.to_vec();
    values.extend(vertices.iter().flatten());
    let ints = common_integers(&values);
    let emin = values.iter().map(|&v| exact_parts(v).1).min().unwrap_or(0);
    let point = |i: usize| -> V { core::array::from_fn(|k| ints[3 * i + k].clone()) };
    let q = point(0);
    let mut least: Option<Frac> = None;
    let mut ties = Vec::new();
    for (index, t) in triangles.iter().enumerate() {
        if !counts(index) {
            continue;
        }
        let [a, b, c] = t.map(|v| point(v as usize + 1));
        let d = triangle(&q, &a, &b, &c);
        match &least {
            Some(l) if d > *l => {}
            Some(l) if d == *l => ties.push(index),
            _ => {
                least = Some(d);
                ties = vec![index];
            }
        }
    }
    // Integers are in units of 2^emin, squared distances of 2^(2 emin).
    let least = least.map(|d| {
        let e = 2 * emin as i64;
        if e >= 0 {
            Frac::new(d.num << e as usize, d.den)
        } else {
            Frac::new(d.num, d.den << (-e) as usize)
        }
    });
    Closest { least, ties }
}
