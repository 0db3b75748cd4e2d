//! How many random cases each property runs: the quick mode, and the long mode of
//! `WALKER_LONG_TESTS=1`.

/// Multiplier of the case counts when `WALKER_LONG_TESTS=1`.
pub const LONG_FACTOR: u32 = 40;

/// Number of random cases per property: `PROPTEST_CASES` (default 256), times
/// [`LONG_FACTOR`] when the environment variable `WALKER_LONG_TESTS` is `1`.
#[must_use]
pub fn cases() -> u32 {
    let base = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse::<u32>().ok())
        .unwrap_or(256);
    let long = std::env::var("WALKER_LONG_TESTS").is_ok_and(|v| v == "1");
    if long {
        base.saturating_mul(LONG_FACTOR)
    } else {
        base
    }
}
