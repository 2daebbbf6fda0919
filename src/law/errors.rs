//! Measured errors of the analytic laws against the full Lennard-Jones
//! sphere solution, over Tabor parameter and load: the one table behind
//! both the planner's choice of law (`law.kind = "auto"`) and the adhesion
//! map (`asperity map`), so the two cannot disagree.
//!
//! The table (`data/law_errors.json`, embedded at build time) stores, for
//! each law, Tabor parameter `mu_i` and load `Pbar_j = P/(pi w R)` on the
//! attached branch of the full solution, the error
//!
//! ```text
//! e = |P_law(delta) - P_LJ(delta)| / (pi w R + |P_LJ(delta)|)
//! ```
//!
//! at the interference `delta` where the full solution carries `Pbar_j`:
//! a relative load error that stays meaningful where the load crosses zero.
//! The file says how it was made and the command that regenerates it.

use super::LawKind;
use serde::Deserialize;
use std::sync::OnceLock;

/// The laws the planner may choose for rough surfaces, cheapest first
/// (DMT has closed forms; Bradley needs bounded heights and is map-only).
pub const PLANNER_LAWS: [LawKind; 4] =
    [LawKind::Hertz, LawKind::Dmt, LawKind::Jkr, LawKind::Maugis];

/// One law's errors: `errors[i][j]` at `mu[i]`, `load_bar[j]`.
#[derive(Debug, Clone, Deserialize)]
pub struct LawErrors {
    /// Law name (`"dmt"`, ...).
    pub law: String,
    /// Errors, rows over `mu`, columns over `load_bar`; `null` (NaN) where
    /// the law has no state at that load (e.g. below its own pull-off).
    pub errors: Vec<Vec<Option<f64>>>,
}

/// The measured error table.
#[derive(Debug, Clone, Deserialize)]
pub struct LawErrorTable {
    /// How the table was made.
    pub provenance: String,
    /// The command that regenerates it.
    pub command: String,
    /// Tabor parameters, ascending.
    pub mu: Vec<f64>,
    /// Loads `P/(pi w R)`, ascending.
    pub load_bar: Vec<f64>,
    /// One entry per law.
    pub laws: Vec<LawErrors>,
}

static EMBEDDED: OnceLock<LawErrorTable> = OnceLock::new();

impl LawErrorTable {
    /// The table shipped with this build (`data/law_errors.json`).
    pub fn embedded() -> &'static LawErrorTable {
        EMBEDDED.get_or_init(|| {
            serde_json::from_str(include_str!("../../data/law_errors.json"))
                .expect("data/law_errors.json is checked by a unit test")
        })
    }

    /// A one-line source for plan printouts.
    pub fn provenance_short(&self) -> String {
        format!("data/law_errors.json, {}", self.command)
    }

    fn law(&self, kind: LawKind) -> Option<&LawErrors> {
        self.laws.iter().find(|l| l.law == kind.name())
    }

    /// Worst error of `kind` over every tabulated load at `mu[i]`
    /// (`inf` if any load has no state).
    fn worst_at(&self, kind: LawKind, i: usize) -> Option<f64> {
        let row = self.law(kind)?.errors.get(i)?;
        Some(
            row.iter()
                .map(|e| e.unwrap_or(f64::INFINITY))
                .fold(0.0, f64::max),
        )
    }

    /// Worst error of `kind` over the tabulated loads at Tabor parameter
    /// `mu`, interpolated linearly in `(ln mu, ln e)` between the tabulated
    /// `mu`; outside the table the nearest end is used. `None` if the law
    /// is not in the table.
    pub fn error(&self, kind: LawKind, mu: f64) -> Option<f64> {
        let n = self.mu.len();
        if n == 0 || !mu.is_finite() {
            return None;
        }
        let i = self.mu.partition_point(|&m| m <= mu);
        if i == 0 {
            return self.worst_at(kind, 0);
        }
        if i == n {
            return self.worst_at(kind, n - 1);
        }
        let (e0, e1) = (self.worst_at(kind, i - 1)?, self.worst_at(kind, i)?);
        if !(e0.is_finite() && e1.is_finite()) || e0 <= 0.0 || e1 <= 0.0 {
            return Some(e0.max(e1));
        }
        let t = (mu.ln() - self.mu[i - 1].ln()) / (self.mu[i].ln() - self.mu[i - 1].ln());
        Some((e0.ln() + t * (e1.ln() - e0.ln())).exp())
    }

    /// The cheapest adhesive planner law whose error at `mu` is `<= rtol`,
    /// with that error.
    pub fn cheapest_within(&self, mu: f64, rtol: f64) -> Option<(LawKind, f64)> {
        PLANNER_LAWS
            .iter()
            .filter(|k| k.is_adhesive())
            .find_map(|&k| self.error(k, mu).filter(|&e| e <= rtol).map(|e| (k, e)))
    }

    /// The adhesive planner law with the smallest error at `mu`.
    pub fn most_accurate(&self, mu: f64) -> (LawKind, f64) {
        PLANNER_LAWS
            .iter()
            .filter(|k| k.is_adhesive())
            .filter_map(|&k| self.error(k, mu).map(|e| (k, e)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((LawKind::Maugis, f64::NAN))
    }

    /// Whether `kind` is within `tol` of the full solution at table point
    /// `(mu[i], load_bar[j])` (the adhesion map's cell test).
    pub fn within(&self, kind: LawKind, i: usize, j: usize, tol: f64) -> bool {
        self.law(kind)
            .and_then(|l| l.errors.get(i)?.get(j).copied().flatten())
            .is_some_and(|e| e <= tol)
    }
}
