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

/// One law's errors: `errors[i][j]` at `mu[i]`, `load_bar[j]`; `null`
/// where the law has no finite load at that interference (a rigid law past
/// its divergence) or where the full solution never carries that load.
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
    /// Interference `Dbar` of the full solution at each `(mu[i],
    /// load_bar[j])`; `null` where the full solution never carries that
    /// load (below its pull-off): such cells are not compared.
    pub reference_interference_bar: Vec<Vec<Option<f64>>>,
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

    /// Whether the full solution carries load `load_bar[j]` at `mu[i]`.
    pub fn has_reference(&self, i: usize, j: usize) -> bool {
        self.reference_interference_bar
            .get(i)
            .and_then(|r| r.get(j).copied().flatten())
            .is_some()
    }

    /// Worst error of `kind` over the tabulated loads the full solution
    /// carries at `mu[i]` (`inf` where the law has no state).
    fn worst_at(&self, kind: LawKind, i: usize) -> Option<f64> {
        let row = self.law(kind)?.errors.get(i)?;
        Some(
            row.iter()
                .enumerate()
                .filter(|(j, _)| self.has_reference(i, *j))
                .map(|(_, e)| e.unwrap_or(f64::INFINITY))
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
        self.has_reference(i, j)
            && self
                .law(kind)
                .and_then(|l| l.errors.get(i)?.get(j).copied().flatten())
                .is_some_and(|e| e <= tol)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_table_is_complete_and_consistent() {
        let t = LawErrorTable::embedded();
        assert!(t.mu.len() >= 10 && t.load_bar.len() >= 10);
        assert!(t.mu.windows(2).all(|w| w[0] < w[1]));
        assert!(t.load_bar.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(t.reference_interference_bar.len(), t.mu.len());
        for k in [
            LawKind::Hertz,
            LawKind::Bradley,
            LawKind::Dmt,
            LawKind::Jkr,
            LawKind::Maugis,
        ] {
            let l = t.law(k).unwrap_or_else(|| panic!("{} missing", k.name()));
            assert_eq!(l.errors.len(), t.mu.len());
            assert!(l.errors.iter().all(|r| r.len() == t.load_bar.len()));
        }
        // Every mu has the zero-load column.
        let j0 = t.load_bar.iter().position(|&p| p == 0.0).unwrap();
        assert!((0..t.mu.len()).all(|i| t.has_reference(i, j0)));
    }

    #[test]
    fn errors_follow_the_theory_limits() {
        let t = LawErrorTable::embedded();
        // JKR improves as mu grows, and is the better of JKR/DMT at large mu.
        let jkr: Vec<f64> = [1.0, 3.0, 10.0]
            .iter()
            .map(|&m| t.error(LawKind::Jkr, m).unwrap())
            .collect();
        assert!(jkr[0] > jkr[1] && jkr[1] > jkr[2], "{jkr:?}");
        assert!(t.error(LawKind::Dmt, 10.0).unwrap() > jkr[2]);
        // The Maugis-Dugdale law is never worse than JKR over mu >= 0.3.
        for m in [0.3, 1.0, 3.0, 10.0] {
            assert!(
                t.error(LawKind::Maugis, m).unwrap() <= t.error(LawKind::Jkr, m).unwrap() * 1.01
            );
        }
        // Rigid Bradley is good at small mu for tensile loads, hopeless at large.
        let (i0, j) = (0, 0);
        assert!(t.within(LawKind::Bradley, i0, j, 1e-2));
        assert!(!t.within(LawKind::Bradley, t.mu.len() - 1, t.load_bar.len() - 1, 0.5));
        // Interpolation in mu stays between neighbours; ends are held.
        let e = t.error(LawKind::Jkr, 4.0).unwrap();
        assert!(e < t.error(LawKind::Jkr, 3.0).unwrap() && e > t.error(LawKind::Jkr, 5.0).unwrap());
        assert_eq!(t.error(LawKind::Jkr, 1e3), t.error(LawKind::Jkr, 10.0));
        assert_eq!(t.error(LawKind::Jkr, f64::NAN), None);
    }

    #[test]
    fn planner_choices_follow_the_table() {
        let t = LawErrorTable::embedded();
        // Deep in JKR territory a loose tolerance picks JKR (DMT fails there).
        assert_eq!(
            t.cheapest_within(800.0, 1e-2).map(|c| c.0),
            Some(LawKind::Jkr)
        );
        // Nothing analytic meets 1e-6 of the full solution.
        assert!(t.cheapest_within(1.0, 1e-6).is_none());
        assert_eq!(t.most_accurate(1.0).0, LawKind::Maugis);
    }
}
