//! Self-test of the exact oracle's conventions (`exactray-oracle`, the
//! tests' ground truth): the signs of known configurations.

use exactray_oracle::oracle::*;
use num_bigint::BigInt;

#[test]
fn conventions() {
    assert_eq!(orient2d([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]), 1);
    assert_eq!(
        orient3d([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        1
    );
    assert_eq!(incircle([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, 0.0]), 1);
    let t = ([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    assert_eq!(insphere(t.0, t.1, t.2, t.3, [0.25; 3]), 1);
    assert_eq!(insphere(t.0, t.1, t.2, t.3, [1.0; 3]), 0);
    assert_eq!(exact_parts(f64::from_bits(1)), (BigInt::from(1), -1074));
    let (q, p) = ([0.0; 3], [1.0, 0.0, 0.0]);
    assert_eq!(
        compare_distance(q, p, [0.0, 0.0, -1.0]),
        core::cmp::Ordering::Equal
    );
    assert_eq!(
        compare_distance(q, p, [1.0, 1e-300, 0.0]),
        core::cmp::Ordering::Less
    );
}
