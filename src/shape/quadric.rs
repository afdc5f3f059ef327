use crate::error::InputError;
use glam::DVec3;

/// The quadric surface
/// `A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0`,
/// from its ten coefficients `[A, B, C, D, E, F, G, H, I, J]`. Its normal
/// at a point is the normalized gradient; where the gradient vanishes (a
/// cone's apex, every point of the all-zero quadric) a cast's normal is the
/// reversed ray direction.
///
/// All ten coefficients zero is a valid quadric: every point satisfies its
/// equation, so every line lies on it, as a ruling lies on a cone.
/// [`line_roots`](Quadric::line_roots) gives [`Roots::All`](crate::roots::Roots::All)
/// for every ray, and a cast hits at the point of its range nearest
/// `t = 0`, as for any line on a surface.
///
/// ```
/// use exactray::shape::Quadric;
/// use exactray::query::ray::RayCast;
/// use exactray::interval::Interval;
/// use exactray::query::ray::Ray;
/// use exactray::roots::Roots;
/// // The paraboloid z = x^2 + y^2.
/// let bowl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0]).unwrap();
/// let down = Ray::new([1.0, 0.0, 5.0], [0.0, 0.0, -1.0]).unwrap();
/// assert_eq!(bowl.line_roots(&down), Roots::One(4.0));
/// assert_eq!(bowl.cast(&down, Interval::FORWARD).unwrap().point.to_array(), [1.0, 0.0, 1.0]);
///
/// // All-zero coefficients: every line lies on the "surface".
/// let everything = Quadric::new([0.0; 10]).unwrap();
/// assert_eq!(everything.line_roots(&down), Roots::All);
/// let hit = everything.cast(&down, Interval::new(2.0, 3.0).unwrap()).unwrap();
/// assert_eq!((hit.t, hit.normal.to_array()), (2.0, [0.0, 0.0, 1.0]));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quadric {
    pub(crate) k: [f64; 10],
}

impl Quadric {
    /// A quadric. Errors: [`InputError::NonFinite`] naming `"coefficients"`
    /// for a NaN or infinite coefficient. All-zero coefficients are
    /// accepted: the quadric every point lies on (see [`Quadric`]).
    pub fn new(coefficients: [f64; 10]) -> Result<Quadric, InputError> {
        if coefficients.iter().any(|v| !v.is_finite()) {
            return Err(InputError::NonFinite {
                argument: "coefficients",
            });
        }
        Ok(Quadric { k: coefficients })
    }

    /// The coefficients `[A, B, C, D, E, F, G, H, I, J]`.
    #[inline]
    pub fn coefficients(&self) -> [f64; 10] {
        self.k
    }

    /// The gradient at `x` (not normalized): `2 M x + (G, H, I)` for the
    /// symmetric matrix `M` of the quadratic part.
    #[inline]
    pub fn gradient(&self, x: DVec3) -> DVec3 {
        let [a, b, c, d, e, f, g, h, i, _] = self.k;
        DVec3::new(
            2.0 * a * x.x + d * x.y + e * x.z + g,
            d * x.x + 2.0 * b * x.y + f * x.z + h,
            e * x.x + f * x.y + 2.0 * c * x.z + i,
        )
    }
}

serde_by_constructor!(
    Quadric as "Quadric" { coefficients: [f64; 10] },
    parts: |q| q.k,
    build: |d| Quadric::new(d.coefficients),
);
