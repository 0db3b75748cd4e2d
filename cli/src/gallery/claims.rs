//! A claim of the gallery: a sentence stating what the run should find and why, what it found,
//! and whether that bears the sentence out. The summary prints each one with `[holds]` or
//! `[FAILS]` in front; a failing claim is a result, not an error of the job.

use std::fmt::Write as _;

/// One claim and its check.
#[derive(Clone, Debug, PartialEq)]
pub struct Claim {
    /// What the run should find, and why (with the numbers it expects).
    pub text: String,
    /// What it found.
    pub found: String,
    /// Whether the finding bears the claim out.
    pub holds: bool,
}

impl Claim {
    /// A claim `text`, its finding `found` and the verdict `holds`.
    #[must_use]
    pub fn new(text: impl Into<String>, found: impl Into<String>, holds: bool) -> Claim {
        Claim {
            text: text.into(),
            found: found.into(),
            holds,
        }
    }

    /// The claim as one item of the summary: `- [holds] text Found: found`.
    #[must_use]
    pub fn line(&self) -> String {
        let verdict = if self.holds { "holds" } else { "FAILS" };
        format!("- [{verdict}] {} Found: {}", self.text, self.found)
    }
}

/// `claim`, or where it could not be computed (no held gait, no sweep, a model that cannot be
/// built) a failing claim named `what`.
#[must_use]
pub fn or_missing(claim: Option<Claim>, what: &str) -> Claim {
    claim.unwrap_or_else(|| {
        Claim::new(
            format!("{what}."),
            "not computed: no held gait, sweep or model to check it on",
            false,
        )
    })
}

/// The claims as summary items, then the tally `N of M claims hold`.
#[must_use]
pub fn table(claims: &[Claim]) -> String {
    let mut s = String::new();
    for c in claims {
        let _ = writeln!(s, "{}", c.line());
    }
    s
}

/// `N of M claims hold`.
#[must_use]
pub fn tally(claims: &[Claim]) -> String {
    let n = claims.iter().filter(|c| c.holds).count();
    format!("{n} of {} claims hold", claims.len())
}
