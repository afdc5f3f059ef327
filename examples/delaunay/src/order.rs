//! The insertion order: a biased randomized insertion order (BRIO, Amenta,
//! Choi and Rote, "Incremental constructions con BRIO", SoCG 2003), each
//! round sorted along a Hilbert curve, so that consecutive points are
//! close and the walk from the last insertion is short, while the rounds
//! keep the randomized algorithm's expected bounds.
//!
//! The curve runs over the points' coordinate *ranks*, not their values: a
//! rank is the same for `x` and `x * 2^k`, so the order (and so the work)
//! is the same for a point set at `1e-160`, at `1e160`, or spread from
//! `1e-300` to `1e300`, where a grid over the values would put almost every
//! point in one cell.

use exactray::testing::SplitMix64;
use glam::DVec2;

/// The indices of `points` in insertion order: every index once. Points
/// must be finite (ranks compare with `total_cmp`, under which `-0.0` and
/// `0.0` differ; that only changes an order, never a result).
pub fn insertion_order(points: &[DVec2]) -> Vec<u32> {
    let n = points.len();
    let x_rank = ranks(points.iter().map(|p| p.x));
    let y_rank = ranks(points.iter().map(|p| p.y));
    // Curve order: enough bits for the largest rank.
    let order = (usize::BITS - (n.max(2) - 1).leading_zeros()) as u8;
    // Round r (0 first) holds a point with probability 2^(r - rounds), the
    // last round half of them: `rounds - trailing zeros` of a random word.
    let rounds = u64::from(order);
    // The round in the top 6 bits of the key, the curve position below.
    let curve_bits = 2 * u32::from(order);
    let drop = curve_bits.saturating_sub(58);
    let mut rng = SplitMix64::for_inputs("exactray-delaunay", "brio");
    let mut keys: Vec<(u64, u32)> = (0..n)
        .map(|i| {
            let depth = u64::from(rng.next_u64().trailing_zeros()).min(rounds);
            let h: u64 = fast_hilbert::xy2h(x_rank[i], y_rank[i], order);
            ((rounds - depth) << 58 | h >> drop, i as u32)
        })
        .collect();
    radsort::sort_by_key(&mut keys, |k| k.0);
    keys.into_iter().map(|(_, i)| i).collect()
}

/// The rank of each value among all of them in `f64::total_cmp`'s order
/// (ties broken by index).
fn ranks(values: impl Iterator<Item = f64>) -> Vec<u32> {
    // A radix sort of the total order's integer images beside their
    // indices (stable: ties keep the index order).
    let mut by: Vec<(u64, u32)> = values
        .zip(0u32..)
        .map(|(v, i)| (total_order_bits(v), i))
        .collect();
    radsort::sort_by_key(&mut by, |k| k.0);
    let mut rank = vec![0u32; by.len()];
    for (r, &(_, i)) in by.iter().enumerate() {
        rank[i as usize] = r as u32;
    }
    rank
}

/// An unsigned integer in the order of `f64::total_cmp`: the sign bit
/// flipped for positive values, every bit for negative ones.
fn total_order_bits(v: f64) -> u64 {
    let bits = v.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_index_once() {
        let pts: Vec<DVec2> = (0..1000)
            .map(|i| DVec2::new((i * 37 % 101) as f64, (i * 11 % 7) as f64))
            .collect();
        let mut order = insertion_order(&pts);
        order.sort_unstable();
        assert_eq!(order, (0..1000).collect::<Vec<u32>>());
        assert!(insertion_order(&[]).is_empty());
        assert_eq!(insertion_order(&[DVec2::ZERO]), vec![0]);
    }

    #[test]
    fn integer_images_keep_the_total_order() {
        let values = [
            f64::MIN,
            -1.0,
            -f64::MIN_POSITIVE,
            -5e-324,
            -0.0,
            0.0,
            5e-324,
            1.0,
            f64::MAX,
        ];
        for w in values.windows(2) {
            assert!(total_order_bits(w[0]) < total_order_bits(w[1]), "{w:?}");
        }
    }

    #[test]
    fn scale_does_not_change_the_order() {
        let pts: Vec<DVec2> =
            exactray::testing::plane_points(exactray::testing::PlaneDistribution::Uniform, 5000)
                .collect();
        let tiny: Vec<DVec2> = pts.iter().map(|p| *p * 2f64.powi(-500)).collect();
        assert_eq!(insertion_order(&pts), insertion_order(&tiny));
    }
}
