//! `predicates::robust_compat` against the `robust` crate it stands in for
//! and against the exact oracle.
//!
//! - Sign conventions: each function's sign on textbook configurations
//!   equals `robust`'s, and `orient3d` and `insphere` are the opposite of
//!   the crate's own (CGAL's) predicates.
//! - Where `robust` is exact (moderate coordinates, uniform): the same sign
//!   on every case and, almost everywhere, the same value to the bit.
//! - Everywhere (the hard classes of `exactray::testing`): the exact
//!   oracle's sign on every case, with a count of the cases where `robust`
//!   is wrong (run with `--nocapture` to see the table); on explicit cases
//!   near `1e-160`, `1e+160` and `1e-300` beside `1e+300`, `robust` is wrong
//!   and the door is not.
//! - A user's code (a convex hull written against `robust`) compiled on
//!   both with only its `use` line changed: the same hull on ordinary
//!   points, and only the door's is a hull where the products underflow.

use exactray::predicates::robust_compat::{self, Coord, Coord3D};
use exactray::testing::{
    InputClass, SplitMix64, incircle_case, insphere_case, orient2d_case, orient3d_case,
};
use exactray_oracle::oracle;

/// The `robust` crate on this crate's point types: its coordinates passed
/// over field by field.
mod theirs {
    use exactray::predicates::robust_compat::{Coord, Coord3D};

    fn c<T: Into<f64>>(p: Coord<T>) -> robust::Coord<f64> {
        robust::Coord {
            x: p.x.into(),
            y: p.y.into(),
        }
    }

    fn c3<T: Into<f64>>(p: Coord3D<T>) -> robust::Coord3D<f64> {
        robust::Coord3D {
            x: p.x.into(),
            y: p.y.into(),
            z: p.z.into(),
        }
    }

    pub fn orient2d<T: Into<f64>>(a: Coord<T>, b: Coord<T>, c_: Coord<T>) -> f64 {
        robust::orient2d(c(a), c(b), c(c_))
    }

    pub fn incircle<T: Into<f64>>(a: Coord<T>, b: Coord<T>, c_: Coord<T>, d: Coord<T>) -> f64 {
        robust::incircle(c(a), c(b), c(c_), c(d))
    }

    pub fn orient3d<T: Into<f64>>(
        a: Coord3D<T>,
        b: Coord3D<T>,
        c: Coord3D<T>,
        d: Coord3D<T>,
    ) -> f64 {
        robust::orient3d(c3(a), c3(b), c3(c), c3(d))
    }

    pub fn insphere<T: Into<f64>>(
        a: Coord3D<T>,
        b: Coord3D<T>,
        c: Coord3D<T>,
        d: Coord3D<T>,
        e: Coord3D<T>,
    ) -> f64 {
        robust::insphere(c3(a), c3(b), c3(c), c3(d), c3(e))
    }
}

/// The sign a caller reads with `> 0.0`, `< 0.0`, `== 0.0`; `None` for NaN,
/// which answers none of them.
fn sign_of(v: f64) -> Option<i8> {
    if v > 0.0 {
        Some(1)
    } else if v < 0.0 {
        Some(-1)
    } else if v == 0.0 {
        Some(0)
    } else {
        None
    }
}

/// The four predicates, for the per-class table.
#[derive(Clone, Copy, Debug)]
enum Predicate {
    Orient2d,
    Orient3d,
    Incircle,
    Insphere,
}

impl Predicate {
    const ALL: [Predicate; 4] = [
        Predicate::Orient2d,
        Predicate::Orient3d,
        Predicate::Incircle,
        Predicate::Insphere,
    ];

    fn name(self) -> &'static str {
        match self {
            Predicate::Orient2d => "orient2d",
            Predicate::Orient3d => "orient3d",
            Predicate::Incircle => "incircle",
            Predicate::Insphere => "insphere",
        }
    }
}

/// robust's value, the door's value and the exact sign in Shewchuk's
/// convention, on one case of a predicate.
type Answers = (f64, f64, i8);

fn on_orient2d([a, b, c]: [[f64; 2]; 3]) -> Answers {
    let p = |[x, y]: [f64; 2]| Coord { x, y };
    (
        theirs::orient2d(p(a), p(b), p(c)),
        robust_compat::orient2d(p(a), p(b), p(c)),
        oracle::orient2d(a, b, c),
    )
}

fn on_orient3d([a, b, c, d]: [[f64; 3]; 4]) -> Answers {
    let p = |[x, y, z]: [f64; 3]| Coord3D { x, y, z };
    (
        theirs::orient3d(p(a), p(b), p(c), p(d)),
        robust_compat::orient3d(p(a), p(b), p(c), p(d)),
        // The oracle is CGAL's orientation, Shewchuk's negated.
        -oracle::orient3d(a, b, c, d),
    )
}

fn on_incircle([a, b, c, d]: [[f64; 2]; 4]) -> Answers {
    let p = |[x, y]: [f64; 2]| Coord { x, y };
    (
        theirs::incircle(p(a), p(b), p(c), p(d)),
        robust_compat::incircle(p(a), p(b), p(c), p(d)),
        oracle::incircle(a, b, c, d),
    )
}

fn on_insphere([a, b, c, d, e]: [[f64; 3]; 5]) -> Answers {
    let p = |[x, y, z]: [f64; 3]| Coord3D { x, y, z };
    (
        theirs::insphere(p(a), p(b), p(c), p(d), p(e)),
        robust_compat::insphere(p(a), p(b), p(c), p(d), p(e)),
        // The oracle is CGAL's oriented sphere, Shewchuk's negated.
        -oracle::insphere(a, b, c, d, e),
    )
}

/// One generated case of a predicate and class: its answers and its
/// points, for a failure message.
fn evaluate(predicate: Predicate, class: InputClass, rng: &mut SplitMix64) -> (Answers, String) {
    match predicate {
        Predicate::Orient2d => {
            let case = orient2d_case(class, rng).map(|p| p.to_array());
            (on_orient2d(case), format!("{case:?}"))
        }
        Predicate::Orient3d => {
            let case = orient3d_case(class, rng).map(|p| p.to_array());
            (on_orient3d(case), format!("{case:?}"))
        }
        Predicate::Incircle => {
            let case = incircle_case(class, rng).map(|p| p.to_array());
            (on_incircle(case), format!("{case:?}"))
        }
        Predicate::Insphere => {
            let case = insphere_case(class, rng).map(|p| p.to_array());
            (on_insphere(case), format!("{case:?}"))
        }
    }
}

#[test]
fn sign_conventions_are_robusts() {
    let p2 = |x: f64, y: f64| Coord { x, y };
    let p3 = |x: f64, y: f64, z: f64| Coord3D { x, y, z };

    // orient2d: counterclockwise is positive, in both and in the crate's own.
    let (a, b, c) = (p2(0.0, 0.0), p2(1.0, 0.0), p2(0.0, 1.0));
    for (x, y, z, expected) in [(a, b, c, 1), (a, c, b, -1), (a, b, p2(2.0, 0.0), 0)] {
        assert_eq!(sign_of(theirs::orient2d(x, y, z)), Some(expected));
        assert_eq!(sign_of(robust_compat::orient2d(x, y, z)), Some(expected));
        let own = exactray::predicates::orient2d([x.x, x.y], [y.x, y.y], [z.x, z.y]);
        assert_eq!(
            own.as_i8(),
            expected,
            "orient2d: the crate's own sign is robust's"
        );
    }

    // orient3d: d above the counterclockwise a, b, c is negative in
    // Shewchuk's convention, positive in the crate's own (CGAL's).
    let (a, b, c) = (p3(0.0, 0.0, 0.0), p3(1.0, 0.0, 0.0), p3(0.0, 1.0, 0.0));
    let arr = |p: Coord3D<f64>| [p.x, p.y, p.z];
    for (d, expected) in [
        (p3(0.0, 0.0, 1.0), -1),
        (p3(0.0, 0.0, -1.0), 1),
        (p3(0.3, 0.7, 0.0), 0),
    ] {
        assert_eq!(sign_of(theirs::orient3d(a, b, c, d)), Some(expected));
        assert_eq!(sign_of(robust_compat::orient3d(a, b, c, d)), Some(expected));
        let own = exactray::predicates::orient3d(arr(a), arr(b), arr(c), arr(d));
        assert_eq!(
            own.as_i8(),
            -expected,
            "orient3d: the crate's own sign is the opposite"
        );
    }

    // incircle: inside the circle through counterclockwise a, b, c is
    // positive, and the sign flips with their order.
    let (a, b, c) = (p2(1.0, 0.0), p2(0.0, 1.0), p2(-1.0, 0.0));
    for (d, expected) in [(p2(0.0, 0.0), 1), (p2(0.0, -1.0), 0), (p2(2.0, 0.0), -1)] {
        assert_eq!(sign_of(theirs::incircle(a, b, c, d)), Some(expected));
        assert_eq!(sign_of(robust_compat::incircle(a, b, c, d)), Some(expected));
        assert_eq!(
            sign_of(robust_compat::incircle(b, a, c, d)),
            Some(-expected)
        );
        let own = exactray::predicates::incircle([a.x, a.y], [b.x, b.y], [c.x, c.y], [d.x, d.y]);
        assert_eq!(
            own.as_i8(),
            expected,
            "incircle: the crate's own sign is robust's"
        );
    }

    // insphere: with robust's orient3d positive (d below the
    // counterclockwise a, b, c), inside is positive; the crate's own
    // insphere, on its own orientation, is the opposite.
    let (a, b, c, d) = (
        p3(0.0, 0.0, 0.0),
        p3(1.0, 0.0, 0.0),
        p3(0.0, 1.0, 0.0),
        p3(0.0, 0.0, -1.0),
    );
    assert!(theirs::orient3d(a, b, c, d) > 0.0);
    for (e, expected) in [
        (p3(0.25, 0.25, -0.25), 1),
        (p3(1.0, 1.0, -1.0), 0),
        (p3(2.0, 2.0, -2.0), -1),
    ] {
        assert_eq!(sign_of(theirs::insphere(a, b, c, d, e)), Some(expected));
        assert_eq!(
            sign_of(robust_compat::insphere(a, b, c, d, e)),
            Some(expected)
        );
        // Swapping two points flips the orientation and the sign.
        assert_eq!(
            sign_of(robust_compat::insphere(b, a, c, d, e)),
            Some(-expected)
        );
        let own = exactray::predicates::insphere(arr(a), arr(b), arr(c), arr(d), arr(e));
        assert_eq!(
            own.as_i8(),
            -expected,
            "insphere: the crate's own sign is the opposite"
        );
    }
}

/// Coordinates uniform in `[-1000, 1000)`: no product underflows or
/// overflows, so robust is exact, and its first stage answers almost every
/// case. The door must give the same sign everywhere, and the same value
/// to the bit wherever its own first stage is within `2^-40` of itself
/// (about 99% of these cases; the others, mostly in-circle and in-sphere
/// cases whose bound is wider, get the exact determinant rounded).
#[test]
fn same_answers_as_robust_where_robust_is_exact() {
    let mut rng = SplitMix64::new(17);
    let mut coordinate = move || 2000.0 * rng.next_f64() - 1000.0;
    let cases = 20_000;
    let mut identical = 0;
    for _ in 0..cases {
        let mut p2 = || Coord {
            x: coordinate(),
            y: coordinate(),
        };
        let [a, b, c, d] = [p2(), p2(), p2(), p2()];
        for (theirs, ours) in [
            (theirs::orient2d(a, b, c), robust_compat::orient2d(a, b, c)),
            (
                theirs::incircle(a, b, c, d),
                robust_compat::incircle(a, b, c, d),
            ),
        ] {
            assert_eq!(sign_of(theirs), sign_of(ours), "{a:?} {b:?} {c:?} {d:?}");
            identical += usize::from(theirs.to_bits() == ours.to_bits());
        }
        let e = p2();
        let [a, b, c, d, e] = [a, b, c, d, e].map(|p| Coord3D {
            x: p.x,
            y: p.y,
            z: coordinate(),
        });
        for (theirs, ours) in [
            (
                theirs::orient3d(a, b, c, d),
                robust_compat::orient3d(a, b, c, d),
            ),
            (
                theirs::insphere(a, b, c, d, e),
                robust_compat::insphere(a, b, c, d, e),
            ),
        ] {
            assert_eq!(
                sign_of(theirs),
                sign_of(ours),
                "{a:?} {b:?} {c:?} {d:?} {e:?}"
            );
            identical += usize::from(theirs.to_bits() == ours.to_bits());
        }
    }
    println!(
        "uniform: {identical} of {} values identical to robust's",
        4 * cases
    );
    // 79,230 of 80,000 with this seed; a change of the first stages'
    // order of operations would drop it far lower.
    assert!(identical >= 4 * cases - 4 * cases / 50, "{identical}");
}

/// Every class of `exactray::testing`, every predicate: the door's sign is
/// the oracle's on every case; robust's is counted.
#[test]
fn exact_on_every_input_class() {
    let cases_per_class = 3_000;
    let mut table = Vec::new();
    for predicate in Predicate::ALL {
        for class in InputClass::ALL {
            let mut rng = SplitMix64::for_inputs(
                &format!("robust_compat-{}", predicate.name()),
                class.name(),
            );
            let mut robust_wrong = 0;
            for _ in 0..cases_per_class {
                let ((theirs, ours, exact), case) = evaluate(predicate, class, &mut rng);
                assert_eq!(
                    sign_of(ours),
                    Some(exact),
                    "{} {}: {case}: returned {ours:e}",
                    predicate.name(),
                    class.name()
                );
                robust_wrong += usize::from(sign_of(theirs) != Some(exact));
            }
            table.push((predicate, class, robust_wrong));
        }
    }
    println!(
        "robust's wrong signs (NaN counted wrong) of {cases_per_class} cases per class; the door's: 0"
    );
    for (predicate, class, wrong) in &table {
        println!("{:<9} {:<16} {wrong}", predicate.name(), class.name());
    }
    // Where robust is exact it is right; where products underflow or
    // overflow it is not, and the door is.
    for (predicate, class, wrong) in table {
        match class {
            InputClass::Uniform | InputClass::NearDegenerate | InputClass::Degenerate => {
                assert_eq!(wrong, 0, "{} {}", predicate.name(), class.name())
            }
            InputClass::Tiny | InputClass::Huge | InputClass::Mixed => {
                assert!(wrong > 0, "{} {}", predicate.name(), class.name())
            }
        }
    }
}

/// Explicit cases at the edges of `f64`'s products: robust's sign is wrong
/// (or NaN), the door's is the exact one.
#[test]
fn exact_where_robust_is_wrong() {
    let up = |x: f64| f64::from_bits(x.to_bits() + 1);
    // A positive unit tetrahedron in Shewchuk's orientation (d below the
    // counterclockwise a, b, c) and a point inside its sphere, scaled by s.
    let tetrahedron = |s: f64| {
        let t = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, -1.0],
        ];
        let [a, b, c, d] = t.map(|p| p.map(|x| s * x));
        [a, b, c, d, [s / 4.0, s / 4.0, -s / 4.0]]
    };
    // The unit circle's centre, scaled by s.
    let circle = |s: f64| [[s, 0.0], [0.0, s], [-s, 0.0], [0.0, 0.0]];
    let cases = [
        // c one ulp above the line y = x, at 1e-160: the products are
        // subnormal and the determinant underflows to zero.
        (
            "orient2d 1e-160",
            on_orient2d([[0.0, 0.0], [1e-160, 1e-160], [3e-160, up(3e-160)]]),
        ),
        // The same at 1e+160: the products overflow.
        (
            "orient2d 1e+160",
            on_orient2d([[0.0, 0.0], [1e160, 1e160], [3e160, up(3e160)]]),
        ),
        // 1e-300 above the line through +-1e300 (the README's case).
        (
            "orient2d mixed",
            on_orient2d([[-1e300, -1e300], [1e300, 1e300], [0.0, 1e-300]]),
        ),
        // A unit tetrahedron scaled by 1e-160: volume 1e-480.
        ("orient3d 1e-160", {
            let [a, b, c, d, _] = tetrahedron(1e-160);
            on_orient3d([a, b, c, d])
        }),
        // d 1e-300 off the plane z = 0 spanned by 1e300 vectors.
        (
            "orient3d mixed",
            on_orient3d([
                [0.0; 3],
                [1e300, 1e300, 0.0],
                [-1e300, 1e300, 0.0],
                [1e300, -1e300, 1e-300],
            ]),
        ),
        // Degree-4 terms underflow, then overflow.
        ("incircle 1e-160", on_incircle(circle(1e-160))),
        ("incircle 1e+160", on_incircle(circle(1e160))),
        // Degree-5 terms underflow, then overflow.
        ("insphere 1e-160", on_insphere(tetrahedron(1e-160))),
        ("insphere 1e+160", on_insphere(tetrahedron(1e160))),
    ];
    for (label, (theirs, ours, exact)) in cases {
        assert_ne!(exact, 0, "{label}: the cases are not degenerate");
        assert_eq!(
            sign_of(ours),
            Some(exact),
            "{label}: the door returned {ours:e}"
        );
        assert_ne!(
            sign_of(theirs),
            Some(exact),
            "{label}: robust returned {theirs:e}"
        );
    }
}

#[test]
fn returned_values() {
    let p2 = |x: f64, y: f64| Coord { x, y };
    // Certified first stage: Shewchuk's determinant itself, twice the area.
    assert_eq!(
        robust_compat::orient2d(p2(0.0, 0.0), p2(2.0, 0.0), p2(0.0, 3.0)),
        6.0
    );
    // A zero is positive zero, whatever the first stage's sign of zero.
    let zero = robust_compat::orient2d(p2(0.0, 0.0), p2(-1.0, 0.0), p2(1.0, 0.0));
    assert_eq!(zero.to_bits(), 0.0f64.to_bits());
    // The determinant, 1e-200 * 1e-200, is below the smallest subnormal:
    // the smallest subnormal, with the exact sign.
    let tiny = robust_compat::orient2d(p2(0.0, 0.0), p2(1e-200, 0.0), p2(0.0, 1e-200));
    assert_eq!(tiny, f64::from_bits(1));
    let tiny = robust_compat::orient2d(p2(0.0, 0.0), p2(0.0, 1e-200), p2(1e-200, 0.0));
    assert_eq!(tiny, -f64::from_bits(1));
    // The first stage overflows; the determinant, (2^601, 2^601) x (2^600,
    // 2^600 + 2^-300) = 2^601 * 2^-300, is a normal number: exactly it.
    let (a, b) = (-(2f64.powi(600)), 2f64.powi(600));
    let huge = robust_compat::orient2d(p2(a, a), p2(b, b), p2(0.0, 2f64.powi(-300)));
    assert_eq!(huge, 2f64.powi(301));
    // Beyond f64::MAX: an infinity of the exact sign.
    let m = f64::MAX;
    let beyond = robust_compat::orient2d(p2(-m, -m), p2(m, -m), p2(-m, m));
    assert_eq!(beyond, f64::INFINITY);
}

#[test]
fn non_finite_input_gives_nan() {
    let p2 = |x: f64, y: f64| Coord { x, y };
    let p3 = |x: f64, y: f64, z: f64| Coord3D { x, y, z };
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let (o2, b2) = (p2(0.0, 0.0), p2(bad, 1.0));
        let (o3, b3) = (p3(0.0, 0.0, 0.0), p3(1.0, bad, 0.0));
        let (x2, y2) = (p2(1.0, 0.0), p2(0.0, 1.0));
        let (x3, y3, z3) = (p3(1.0, 0.0, 0.0), p3(0.0, 1.0, 0.0), p3(0.0, 0.0, 1.0));
        for v in [
            robust_compat::orient2d(o2, x2, b2),
            robust_compat::orient2d(b2, o2, x2),
            robust_compat::incircle(o2, x2, y2, b2),
            robust_compat::incircle(b2, x2, y2, o2),
            robust_compat::orient3d(o3, x3, y3, b3),
            robust_compat::orient3d(b3, x3, y3, z3),
            robust_compat::insphere(o3, x3, y3, z3, b3),
            robust_compat::insphere(x3, b3, y3, z3, o3),
        ] {
            assert!(v.is_nan(), "{bad}: {v}");
        }
    }
    // An infinity that would cancel in a careless check is still caught.
    let inf = f64::INFINITY;
    let v = robust_compat::orient2d(p2(inf, 0.0), p2(inf, 0.0), p2(0.0, 1.0));
    assert!(v.is_nan());
}

/// `T: Into<f64>` as in robust: `f32` and integer coordinates widen exactly.
#[test]
fn other_coordinate_types() {
    let i = |x: i32, y: i32| Coord { x, y };
    assert!(robust_compat::orient2d(i(0, 0), i(1, 0), i(0, 1)) > 0.0);
    assert!(robust_compat::incircle(i(1, 0), i(0, 1), i(-1, 0), i(0, -1)) == 0.0);
    let f = |x: f32, y: f32, z: f32| Coord3D { x, y, z };
    let (a, b, c) = (f(0.0, 0.0, 0.0), f(1.0, 0.0, 0.0), f(0.0, 1.0, 0.0));
    assert!(robust_compat::orient3d(a, b, c, f(0.1, 0.2, 0.0)) == 0.0);
    // 0.1f32 is not 0.1f64, but the points are exactly coplanar as given.
    assert_eq!(
        robust_compat::orient3d(a, b, c, f(0.0, 0.0, 1.0)),
        theirs::orient3d(a, b, c, f(0.0, 0.0, 1.0))
    );
    // robust's derives: copied, compared, printed; and the functions as
    // pointers of robust's signature.
    let p = Coord { x: 1.0, y: 2.0 };
    let q = p;
    assert_eq!(p, q);
    assert_eq!(
        format!("{p:?}"),
        format!("{:?}", robust::Coord { x: 1.0, y: 2.0 })
    );
    let as_pointer: fn(Coord<f64>, Coord<f64>, Coord<f64>) -> f64 = robust_compat::orient2d;
    assert!(as_pointer(i2(0.0, 0.0), i2(1.0, 0.0), i2(0.0, 1.0)) > 0.0);
    fn i2(x: f64, y: f64) -> Coord<f64> {
        Coord { x, y }
    }
}

/// A convex hull (Andrew's monotone chain) written against `robust`'s
/// interface, compiled twice: once on `robust` itself and once with its
/// one `use` line swapped for the door. Nothing else differs.
macro_rules! monotone_chain {
    ($module:ident, $predicates:path) => {
        mod $module {
            use $predicates as robust;

            /// The hull's vertices, counterclockwise, collinear points dropped.
            pub fn hull(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
                let mut sorted = points.to_vec();
                sorted.sort_by(|p, q| p.partial_cmp(q).expect("finite points"));
                sorted.dedup();
                if sorted.len() < 3 {
                    return sorted;
                }
                let c = |[x, y]: [f64; 2]| robust::Coord { x, y };
                let turns_left = |h: &[[f64; 2]], p: [f64; 2]| {
                    let n = h.len();
                    robust::orient2d(c(h[n - 2]), c(h[n - 1]), c(p)) > 0.0
                };
                let mut lower: Vec<[f64; 2]> = Vec::new();
                for &p in &sorted {
                    while lower.len() >= 2 && !turns_left(&lower, p) {
                        lower.pop();
                    }
                    lower.push(p);
                }
                let mut upper: Vec<[f64; 2]> = Vec::new();
                for &p in sorted.iter().rev() {
                    while upper.len() >= 2 && !turns_left(&upper, p) {
                        upper.pop();
                    }
                    upper.push(p);
                }
                lower.pop();
                upper.pop();
                lower.extend(upper);
                lower
            }
        }
    };
}

monotone_chain!(hull_on_robust, robust);
monotone_chain!(hull_on_door, exactray::predicates::robust_compat);

/// Whether `hull` is a convex hull of `points`, decided exactly: every turn
/// strictly counterclockwise and no point strictly outside an edge.
fn is_convex_hull(hull: &[[f64; 2]], points: &[[f64; 2]]) -> bool {
    let n = hull.len();
    n >= 3
        && (0..n).all(|i| {
            let (a, b) = (hull[i], hull[(i + 1) % n]);
            oracle::orient2d(a, b, hull[(i + 2) % n]) > 0
                && points.iter().all(|&p| oracle::orient2d(a, b, p) >= 0)
        })
}

/// The swap on a user's code: at ordinary magnitudes both copies build the
/// same hull; scaled by `2^-540` (about `3e-163`), where the products
/// underflow, only the door's is a convex hull of its points.
#[test]
fn a_hull_swapped_in_one_line() {
    let mut rng = SplitMix64::new(160);
    let disk: Vec<[f64; 2]> = (0..400)
        .map(|_| [2.0 * rng.next_f64() - 1.0, 2.0 * rng.next_f64() - 1.0])
        .filter(|[x, y]| x * x + y * y < 1.0)
        .collect();
    let ordinary = hull_on_door::hull(&disk);
    assert!(is_convex_hull(&ordinary, &disk));
    assert_eq!(ordinary, hull_on_robust::hull(&disk));

    // Exact: no scaled coordinate is subnormal.
    let scale = |p: &[f64; 2]| p.map(|x| x * 2f64.powi(-540));
    let tiny: Vec<[f64; 2]> = disk.iter().map(scale).collect();
    let theirs = hull_on_robust::hull(&tiny);
    let ours = hull_on_door::hull(&tiny);
    println!(
        "hull at 2^-540: {} vertices on the door, {} on robust",
        ours.len(),
        theirs.len()
    );
    assert!(is_convex_hull(&ours, &tiny));
    assert!(!is_convex_hull(&theirs, &tiny));
    // The door's hull is the ordinary one, scaled.
    assert_eq!(ours, ordinary.iter().map(scale).collect::<Vec<_>>());
}
