//! The filters' a-priori bounds against exact values: each point's
//! rounded coordinates and weight within `el` and `ew` of the exact ones,
//! and each certified determinant within its bound, on every input class
//! and on cases built to cancel (the origin next to the point, lines
//! nearly parallel to their planes).

#[cfg(test)]
mod tests {
    use crate::predicates::implicit::any::{AnyPoint2, AnyPoint3, Point};
    use crate::predicates::implicit::approx::{self, Hom, det2_bounded, det3_bounded};
    use crate::predicates::implicit::points::{Lpi, Ssi, Tpi};
    use crate::testing::{
        InputClass, SplitMix64, orient2d_ssi_case, orient3d_lpi_case, orient3d_tpi_case, step_ulps,
    };
    use exactray_oracle::oracle::exact_parts;
    use glam::{DVec2, DVec3};
    use num_bigint::BigInt;
    use num_traits::Signed;

    /// An exact value `n 2^e`.
    #[derive(Clone)]
    struct Exact(BigInt, i32);

    impl Exact {
        fn of(v: f64) -> Exact {
            let (m, e) = exact_parts(v);
            Exact(m, e)
        }

        fn at(&self, e: i32) -> BigInt {
            &self.0 << (self.1 - e) as usize
        }

        fn add(&self, o: &Exact) -> Exact {
            let e = self.1.min(o.1);
            Exact(self.at(e) + o.at(e), e)
        }

        fn sub(&self, o: &Exact) -> Exact {
            let e = self.1.min(o.1);
            Exact(self.at(e) - o.at(e), e)
        }

        fn mul(&self, o: &Exact) -> Exact {
            Exact(&self.0 * &o.0, self.1 + o.1)
        }

        /// Whether `|approx - self| <= bound`.
        fn within(&self, approx: f64, bound: f64) -> bool {
            let (a, b) = (Exact::of(approx), Exact::of(bound));
            let e = self.1.min(a.1).min(b.1);
            (a.at(e) - self.at(e)).abs() <= b.at(e)
        }
    }

    type V<const D: usize> = [Exact; D];

    fn v3(p: DVec3) -> V<3> {
        p.to_array().map(Exact::of)
    }

    fn v2(p: DVec2) -> V<2> {
        p.to_array().map(Exact::of)
    }

    fn sub<const D: usize>(a: &V<D>, b: &V<D>) -> V<D> {
        core::array::from_fn(|k| a[k].sub(&b[k]))
    }

    fn cross(a: &V<3>, b: &V<3>) -> V<3> {
        core::array::from_fn(|k| {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            a[i].mul(&b[j]).sub(&a[j].mul(&b[i]))
        })
    }

    fn dot(a: &V<3>, b: &V<3>) -> Exact {
        a[0].mul(&b[0]).add(&a[1].mul(&b[1])).add(&a[2].mul(&b[2]))
    }

    fn perp(a: &V<2>, b: &V<2>) -> Exact {
        a[0].mul(&b[1]).sub(&a[1].mul(&b[0]))
    }

    /// The exact homogeneous coordinates and weight of a point relative to `o`.
    fn exact3(p: &AnyPoint3, o: DVec3) -> (V<3>, Exact) {
        let o = v3(o);
        match p {
            AnyPoint3::Explicit(x) => (sub(&v3(*x), &o), Exact(BigInt::from(1), 0)),
            AnyPoint3::Lpi(x) => {
                let [p, q, r, s, t] = [x.p, x.q, x.r, x.s, x.t].map(v3);
                let n = cross(&sub(&s, &r), &sub(&t, &r));
                let e = sub(&q, &p);
                let (d, pp) = (dot(&n, &e), dot(&n, &sub(&p, &r)));
                let h = sub(&p, &o);
                (
                    core::array::from_fn(|k| h[k].mul(&d).sub(&e[k].mul(&pp))),
                    d,
                )
            }
            AnyPoint3::Tpi(x) => {
                let planes = x.planes.map(|p| p.map(v3));
                let n: [V<3>; 3] = core::array::from_fn(|i| {
                    let [p0, p1, p2] = &planes[i];
                    cross(&sub(p1, p0), &sub(p2, p0))
                });
                let h: [Exact; 3] = core::array::from_fn(|i| dot(&n[i], &sub(&planes[i][0], &o)));
                let c = [
                    cross(&n[1], &n[2]),
                    cross(&n[2], &n[0]),
                    cross(&n[0], &n[1]),
                ];
                let l = core::array::from_fn(|k| {
                    c[0][k]
                        .mul(&h[0])
                        .add(&c[1][k].mul(&h[1]))
                        .add(&c[2][k].mul(&h[2]))
                });
                (l, dot(&n[0], &c[0]))
            }
        }
    }

    fn exact2(p: &AnyPoint2, o: DVec2) -> (V<2>, Exact) {
        let o = v2(o);
        match p {
            AnyPoint2::Explicit(x) => (sub(&v2(*x), &o), Exact(BigInt::from(1), 0)),
            AnyPoint2::Ssi(x) => {
                let [p, q, r, s] = [x.p, x.q, x.r, x.s].map(v2);
                let (e, f) = (sub(&q, &p), sub(&s, &r));
                let (d, t) = (perp(&e, &f), perp(&sub(&r, &p), &f));
                let h = sub(&p, &o);
                (core::array::from_fn(|k| h[k].mul(&d).add(&e[k].mul(&t))), d)
            }
        }
    }

    /// Checks a point's bounds relative to `o`, where its scale is in range.
    fn check_point<const D: usize>(
        h: &Hom<D>,
        exact: &(V<D>, Exact),
        degree: u32,
        what: &str,
    ) -> bool {
        if !approx::in_range(&[*h], degree) {
            return false;
        }
        for k in 0..D {
            assert!(
                exact.0[k].within(h.l[k], h.el),
                "{what}: l[{k}] = {} beyond {}",
                h.l[k],
                h.el
            );
        }
        assert!(
            exact.1.within(h.w, h.ew),
            "{what}: w = {} beyond {}",
            h.w,
            h.ew
        );
        let l = h.l.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        assert!(l <= h.lmax, "{what}: |l| = {l} above lmax {}", h.lmax);
        true
    }

    /// An origin next to the point (so that its coordinates cancel), or one of
    /// the case's own points.
    fn origin(c: &[DVec3], rng: &mut SplitMix64, near: Option<DVec3>) -> DVec3 {
        match (near, rng.next_u64() % 3) {
            (Some(x), 0) if x.is_finite() => x
                .to_array()
                .map(|v| step_ulps(v, (rng.next_u64() % 5) as i64 - 2))
                .into(),
            _ => c[(rng.next_u64() % c.len() as u64) as usize],
        }
    }

    /// A rough `f64` value of a constructed point, for origins next to it.
    fn rough(h: &Hom<3>, o: DVec3) -> DVec3 {
        o + DVec3::from_array(h.l) / h.w
    }

    #[test]
    fn point_bounds_hold() {
        let mut rng = SplitMix64::new(31);
        let mut checked = 0;
        for i in 0..30_000 {
            let class = InputClass::ALL[i % 6];
            let c = orient3d_lpi_case(class, &mut rng);
            let x = AnyPoint3::Lpi(Lpi::new(c[3], c[4], c[5], c[6], c[7]).unwrap());
            let o = origin(&c, &mut rng, Some(rough(&x.approx(c[0].to_array()), c[0])));
            checked += check_point(&x.approx(o.to_array()), &exact3(&x, o), 4, "lpi") as u32;
            let t = orient3d_tpi_case(class, &mut rng);
            let y = AnyPoint3::Tpi(
                Tpi::new([t[3], t[4], t[5]], [t[6], t[7], t[8]], [t[9], t[10], t[11]]).unwrap(),
            );
            let o = origin(&t, &mut rng, Some(rough(&y.approx(t[0].to_array()), t[0])));
            checked += check_point(&y.approx(o.to_array()), &exact3(&y, o), 7, "tpi") as u32;
            let s = orient2d_ssi_case(class, &mut rng);
            let z = AnyPoint2::Ssi(Ssi::new(s[2], s[3], s[4], s[5]).unwrap());
            let o = s[(rng.next_u64() % 6) as usize];
            checked += check_point(&z.approx(o.to_array()), &exact2(&z, o), 3, "ssi") as u32;
        }
        // Tiny, huge and mixed cases are mostly out of range (the scaled filter
        // takes them).
        assert!(checked > 40_000, "{checked}");
    }

    /// The determinants' bounds, on rows from a constructed point and two
    /// explicit ones, and from two and three constructed points.
    #[test]
    fn determinant_bounds_hold() {
        let mut rng = SplitMix64::new(32);
        for i in 0..20_000 {
            let class = InputClass::ALL[i % 6];
            let c = orient3d_lpi_case(class, &mut rng);
            let x = AnyPoint3::Lpi(Lpi::new(c[3], c[4], c[5], c[6], c[7]).unwrap());
            let t = orient3d_tpi_case(class, &mut rng);
            let y = AnyPoint3::Tpi(
                Tpi::new([t[3], t[4], t[5]], [t[6], t[7], t[8]], [t[9], t[10], t[11]]).unwrap(),
            );
            let rows = match i % 3 {
                0 => [AnyPoint3::Explicit(c[1]), AnyPoint3::Explicit(c[2]), x],
                1 => [AnyPoint3::Explicit(c[1]), x, y],
                _ => [x, y, AnyPoint3::Explicit(c[2])],
            };
            let o = c[0];
            let h = rows.map(|p| p.approx(o.to_array()));
            let degree: u32 = rows.iter().map(|p| p.degrees().l).sum();
            if !approx::in_range(&h, degree) {
                continue;
            }
            let e = rows.map(|p| exact3(&p, o).0);
            let det = dot(&e[0], &cross(&e[1], &e[2]));
            let (value, bound) = det3_bounded(h.map(|x| (x.l, x.el)));
            assert!(det.within(value, bound), "{rows:?}: {value} beyond {bound}");
            // The planar determinant of the rows' projections.
            let p = h.map(|x| x.select([(i % 3 + 1) % 3, (i % 3 + 2) % 3]));
            let ep = e.map(|v| [v[(i % 3 + 1) % 3].clone(), v[(i % 3 + 2) % 3].clone()]);
            let (value, bound) = det2_bounded([(p[0].l, p[0].el), (p[1].l, p[1].el)]);
            assert!(
                perp(&ep[0], &ep[1]).within(value, bound),
                "{rows:?}: {value} beyond {bound}"
            );
        }
    }
}
