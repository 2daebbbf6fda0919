//! What `asperity run --plan` shows: the plan, or as much of it as can be
//! decided before the run gathers its expensive inputs.

use super::inputs::Pending;
use super::{Decision, Plan, PlanMode};
use std::fmt;

/// A plan before the run, from [`Plan::preview`].
#[derive(Debug, Clone)]
pub enum Preview {
    /// Every input was at hand: the plan the run will use.
    Ready(Box<Plan>),
    /// The calibration is not cached yet: the plan with Maugis–Dugdale at
    /// the same `lambda` standing in for the range decisions (start,
    /// tables); the run computes the calibration and decides again.
    Provisional(Box<Plan>, Pending),
    /// A measured map decides the rest when the run reads it.
    Pending {
        /// The scene's title.
        title: Option<String>,
        /// The mode.
        mode: PlanMode,
        /// What the run gathers first.
        pending: Pending,
        /// The decisions that do not need it.
        decisions: Vec<Decision>,
    },
}

impl Preview {
    /// The plan, when one could be made.
    pub fn plan(&self) -> Option<&Plan> {
        match self {
            Preview::Ready(p) | Preview::Provisional(p, _) => Some(p),
            Preview::Pending { .. } => None,
        }
    }

    /// The plan's warnings (none while a map is pending).
    pub fn warnings(&self) -> &[crate::study::Warning] {
        self.plan().map_or(&[], |p| &p.warnings)
    }

    /// What `--plan --json` prints: `status` (`"ready"`, `"provisional"`
    /// or `"pending"`), `title`, `decisions` (each `topic`, `choice`,
    /// `why`, as the text shows them), `pending` (what the run gathers
    /// first, or null) and `warnings`.
    pub fn to_json(&self) -> String {
        let (status, title, decisions, pending) = match self {
            Preview::Ready(p) => ("ready", &p.scene.title, &p.decisions, None),
            Preview::Provisional(p, pending) => {
                ("provisional", &p.scene.title, &p.decisions, Some(pending))
            }
            Preview::Pending {
                title,
                pending,
                decisions,
                ..
            } => ("pending", title, decisions, Some(pending)),
        };
        let decisions: Vec<serde_json::Value> = decisions
            .iter()
            .map(|d| {
                serde_json::json!({
                    "topic": d.topic(),
                    "choice": d.choice(),
                    "why": d.why(),
                })
            })
            .collect();
        let v = serde_json::json!({
            "status": status,
            "title": title,
            "decisions": decisions,
            "pending": pending.map(|p| p.to_string()),
            "warnings": self.warnings(),
        });
        serde_json::to_string_pretty(&v).unwrap_or_default()
    }
}

impl fmt::Display for Pending {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Pending::Map(path) => write!(
                f,
                "the map {} is read and characterised when the run starts; the law (at the \
                 map's summit radius), the start separation and the methods are decided from its \
                 summits then",
                path.display()
            ),
            Pending::Calibration { mu, path } => write!(
                f,
                "the full-solver calibration at mu = {mu:.4} is not cached ({}): the run computes \
                 it first (seconds) and decides again; until then Maugis-Dugdale at the same \
                 lambda stands in for the start separation and the tables above",
                path.display()
            ),
        }
    }
}

impl fmt::Display for Preview {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Preview::Ready(p) => write!(f, "{p}"),
            Preview::Provisional(p, pending) => {
                write!(f, "{p}")?;
                writeln!(f, "  {:<18} {}", "pending", pending)
            }
            Preview::Pending {
                title,
                mode,
                pending,
                decisions,
            } => {
                let title = title.as_deref().unwrap_or("untitled scene");
                writeln!(f, "plan for {title} ({mode:?})")?;
                for d in decisions {
                    writeln!(f, "  {:<18} {:<24} {}", d.topic(), d.choice(), d.why())?;
                }
                writeln!(f, "  {:<18} {}", "pending", pending)
            }
        }
    }
}
