//! Chart axes: linear, logarithmic and symmetric-logarithmic scales with
//! their own ticks and labels, as a plotters coordinate.
//!
//! Ticks are whole multiples `k x step` of a 1-2-5 step (so 0 is exactly 0,
//! never `-2.2e-16`), or powers of ten on log scales. Every label of one
//! axis is written in one notation ([`Notation`]): plain when all ticks lie
//! in `[1e-3, 1e5)` in magnitude, else scientific with the mantissa digits
//! the step needs.

use plotters::coord::ranged1d::{KeyPointHint, NoDefaultFormatting, Ranged, ValueFormatter};
use std::ops::Range;

/// How values map to the axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scale {
    /// `x`.
    Linear,
    /// `log10 x` (positive values only).
    Log,
    /// `sign(x) log10(1 + |x|/c)`: linear within `|x| < c`, logarithmic
    /// beyond, for data that change sign and span decades.
    SymLog(f64),
}

/// The one notation of an axis's labels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Notation {
    /// Fixed point with this many decimals.
    Plain(usize),
    /// Scientific (`2.5e-7`) with this many mantissa decimals.
    Sci(usize),
}

impl Notation {
    /// The notation for a set of ticks spaced by `step` (0 for log axes):
    /// plain when every non-zero tick is in `[1e-3, 1e5)` in magnitude.
    pub fn for_ticks(ticks: &[f64], step: f64) -> Notation {
        let plain = ticks
            .iter()
            .filter(|t| **t != 0.0)
            .all(|t| (1e-3..1e5).contains(&t.abs()));
        let step_exp = if step > 0.0 {
            step.log10().floor() as i32
        } else {
            0
        };
        if plain {
            let decimals = if step > 0.0 { (-step_exp).max(0) } else { 3 };
            // Log ticks (step 0) are m x 10^k: as many decimals as the
            // smallest one needs.
            let decimals = if step > 0.0 {
                decimals
            } else {
                ticks
                    .iter()
                    .filter(|t| **t != 0.0)
                    .map(|t| (-((t.abs().log10() + 1e-9).floor() as i32)).max(0))
                    .max()
                    .unwrap_or(0)
            };
            Notation::Plain(decimals as usize)
        } else {
            let top = ticks
                .iter()
                .map(|t| t.abs())
                .fold(0.0f64, f64::max)
                .log10()
                .floor() as i32;
            let digits = if step > 0.0 {
                (top - step_exp).clamp(0, 6)
            } else {
                0
            };
            Notation::Sci(digits as usize)
        }
    }

    /// `v` in this notation; `0` for an exact zero.
    pub fn format(self, v: f64) -> String {
        if v == 0.0 {
            return "0".into();
        }
        let s = match self {
            Notation::Plain(d) => format!("{v:.d$}"),
            Notation::Sci(d) => format!("{v:.d$e}"),
        };
        if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
            s[1..].to_string()
        } else {
            s
        }
    }
}

/// One axis: its range, scale, ticks and the notation of their labels.
#[derive(Debug, Clone)]
pub struct Axis {
    lo: f64,
    hi: f64,
    scale: Scale,
    ticks: Vec<f64>,
    minor: Vec<f64>,
    notation: Notation,
}

/// A 1-2-5 step giving about `n` intervals over `span`.
fn nice_step(span: f64, n: f64) -> f64 {
    let raw = span / n;
    let p = 10f64.powf(raw.log10().floor());
    let m = raw / p;
    let f = if m < 1.5 {
        1.0
    } else if m < 3.5 {
        2.0
    } else if m < 7.5 {
        5.0
    } else {
        10.0
    };
    f * p
}

/// The multiples `k x step` in `[lo, hi]`, computed from integers so
/// that none carries round-off (0 is exactly 0).
fn multiples(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let (k0, k1) = ((lo / step).ceil() as i64, (hi / step).floor() as i64);
    (k0..=k1).map(|k| k as f64 * step).collect()
}

impl Axis {
    /// A linear axis over `[lo, hi]` with about 6 to 10 ticks.
    pub fn linear(lo: f64, hi: f64) -> Axis {
        let (lo, hi) = widen(lo, hi);
        let step = nice_step(hi - lo, 6.0);
        let ticks = multiples(lo, hi, step);
        let minor = multiples(lo, hi, step / 5.0);
        let notation = Notation::for_ticks(&ticks, step);
        Axis {
            lo,
            hi,
            scale: Scale::Linear,
            ticks,
            minor,
            notation,
        }
    }

    /// A logarithmic axis over `[lo, hi]` (both > 0): ticks at powers of
    /// ten (every second or third one over many decades), minor ticks at
    /// `2..9 x 10^k`; over less than two decades 1-2-5 or `1..9 x 10^k`
    /// ticks, and within one of those steps linear 1-2-5 multiples, so that
    /// every axis has at least three labels.
    pub fn log(lo: f64, hi: f64) -> Axis {
        let (e0, e1) = (lo.log10().ceil() as i32, hi.log10().floor() as i32);
        let every = (((e1 - e0) / 9) + 1).max(1);
        let mut ticks: Vec<f64> = (e0..=e1)
            .filter(|e| (e - e0) % every == 0)
            .map(|e| 10f64.powi(e))
            .collect();
        // Under two decades: 1-2-5 ticks (then every 1..9 x 10^k), so
        // that an axis has at least three labels.
        for mantissas in [
            &[1.0, 2.0, 5.0][..],
            &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0],
        ] {
            if ticks.len() >= 3 {
                break;
            }
            ticks = (e0 - 1..=e1)
                .flat_map(|e| mantissas.iter().map(move |m| m * 10f64.powi(e)))
                .filter(|v| *v >= lo && *v <= hi)
                .collect();
        }
        let minor = (e0 - 1..=e1)
            .flat_map(|e| (1..10).map(move |m| m as f64 * 10f64.powi(e)))
            .filter(|v| *v >= lo && *v <= hi)
            .collect();
        // Within one step of the 1..9 mantissas (2.1e-7 .. 3.9e-7): linear
        // 1-2-5 multiples, still at least three labels.
        let mut step = 0.0;
        if ticks.len() < 3 {
            step = nice_step(hi - lo, 4.0);
            ticks = multiples(lo, hi, step);
        }
        let notation = Notation::for_ticks(&ticks, step);
        Axis {
            lo,
            hi,
            scale: Scale::Log,
            ticks,
            minor,
            notation,
        }
    }

    /// A symmetric-logarithmic axis over `[lo, hi]`, linear within
    /// `|x| < c`: ticks at 0 and at `+-10^k` beyond `c / 10`.
    pub fn symlog(lo: f64, hi: f64, c: f64) -> Axis {
        let mut ticks = vec![0.0];
        let e0 = (c / 10.0).log10().ceil() as i32;
        for e in e0..=300 {
            let v = 10f64.powi(e);
            if v > hi.max(-lo) {
                break;
            }
            if v <= hi {
                ticks.push(v);
            }
            if -v >= lo {
                ticks.push(-v);
            }
        }
        let mut axis = Axis {
            lo,
            hi,
            scale: Scale::SymLog(c),
            ticks: Vec::new(),
            minor: Vec::new(),
            notation: Notation::Plain(0),
        };
        // 0 first, then the largest magnitudes: a tick closer than 6 % of
        // the axis to one already kept is dropped (labels never overlap).
        ticks.sort_by(|a, b| {
            (*a != 0.0)
                .cmp(&(*b != 0.0))
                .then(b.abs().total_cmp(&a.abs()))
        });
        let mut kept: Vec<f64> = Vec::new();
        for t in ticks {
            let f = axis.fraction(t);
            if kept.iter().all(|k| (axis.fraction(*k) - f).abs() >= 0.06) {
                kept.push(t);
            }
        }
        kept.sort_by(f64::total_cmp);
        // Light lines at 1..9 x 10^k where the scale is logarithmic.
        axis.minor = (e0 - 1..=hi.max(-lo).log10().ceil() as i32)
            .flat_map(|e| (1..10).map(move |m| m as f64 * 10f64.powi(e)))
            .filter(|v| *v >= c)
            .flat_map(|v| [v, -v])
            .filter(|v| *v >= lo && *v <= hi)
            .collect();
        axis.notation = Notation::for_ticks(&kept, 0.0);
        axis.ticks = kept;
        axis
    }

    /// The axis for data spanning `[lo, hi]` (padded by 3 % of the span on
    /// the transformed scale): symmetric-logarithmic when the data reach
    /// more than two decades beyond `linear_scale` (the magnitude that must
    /// stay readable, e.g. the pull-off), linear otherwise.
    pub fn fit(lo: f64, hi: f64, linear_scale: Option<f64>) -> Axis {
        let big = lo.abs().max(hi.abs());
        match linear_scale.filter(|c| *c > 0.0 && big / c > 1e2) {
            Some(c) => {
                let t = |v: f64| v.signum() * (1.0 + v.abs() / c).log10();
                let inv = |u: f64| u.signum() * c * (10f64.powf(u.abs()) - 1.0);
                let pad = 0.03 * (t(hi) - t(lo));
                Axis::symlog(inv(t(lo) - pad), inv(t(hi) + pad), c)
            }
            None => {
                let pad = 0.03 * (hi - lo);
                Axis::linear(lo - pad, hi + pad)
            }
        }
    }

    /// The same axis drawn from `hi` to `lo` (y growing downwards, as
    /// image rows do).
    pub fn reversed(mut self) -> Axis {
        std::mem::swap(&mut self.lo, &mut self.hi);
        self
    }

    /// The tick values (the labelled ones).
    pub fn ticks(&self) -> &[f64] {
        &self.ticks
    }

    /// The scale.
    pub fn scale(&self) -> Scale {
        self.scale
    }

    /// `v`'s label in the axis's one notation (powers of ten on log
    /// scales without trailing zeros: `10`, `1`, `0.1`).
    pub fn label(&self, v: f64) -> String {
        let s = self.notation.format(v);
        match (self.scale, self.notation) {
            (Scale::Linear, _) | (_, Notation::Sci(_)) => s,
            _ if s.contains('.') => s.trim_end_matches('0').trim_end_matches('.').to_string(),
            _ => s,
        }
    }

    /// The position of `v` on the transformed scale.
    fn t(&self, v: f64) -> f64 {
        match self.scale {
            Scale::Linear => v,
            Scale::Log => v.max(f64::MIN_POSITIVE).log10(),
            Scale::SymLog(c) => v.signum() * (1.0 + v.abs() / c).log10(),
        }
    }

    /// `v` as a fraction of the axis, 0 at `lo` and 1 at `hi`.
    pub fn fraction(&self, v: f64) -> f64 {
        (self.t(v) - self.t(self.lo)) / (self.t(self.hi) - self.t(self.lo))
    }

    /// Whether `v` can be drawn on this axis.
    pub fn accepts(&self, v: f64) -> bool {
        v.is_finite() && (self.scale != Scale::Log || v > 0.0)
    }
}

/// A non-empty range around `[lo, hi]` (a single value gets +-1 or +-10 %).
fn widen(lo: f64, hi: f64) -> (f64, f64) {
    if hi > lo {
        (lo, hi)
    } else {
        let d = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        (lo - d, hi + d)
    }
}

impl Ranged for Axis {
    type FormatOption = NoDefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        let f = self.fraction(*v);
        (limit.0 as f64 + f * (limit.1 - limit.0) as f64).round() as i32
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.minor.clone()
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.lo..self.hi
    }
}

impl ValueFormatter<f64> for Axis {
    fn format_ext(&self, v: &f64) -> String {
        self.label(*v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_are_exact_multiples_and_zero_is_zero() {
        let a = Axis::linear(-1.45, 0.05);
        assert!(a.ticks().contains(&0.0));
        let labels: Vec<String> = a.ticks().iter().map(|t| a.label(*t)).collect();
        assert_eq!(labels.last().unwrap(), "0");
        assert!(labels.iter().all(|l| !l.contains('e')), "{labels:?}");
        assert!(labels.contains(&"-1.4".to_string()), "{labels:?}");
    }

    #[test]
    fn one_notation_per_axis() {
        let a = Axis::linear(0.0, 2.6e4);
        let labels: Vec<String> = a.ticks().iter().map(|t| a.label(*t)).collect();
        assert!(labels.iter().all(|l| !l.contains('e')), "{labels:?}");
        let b = Axis::linear(0.0, 4.2e5);
        let labels: Vec<String> = b.ticks().iter().map(|t| b.label(*t)).collect();
        assert!(
            labels.iter().all(|l| l == "0" || l.contains('e')),
            "{labels:?}"
        );
        assert!(labels.contains(&"1.0e5".to_string()), "{labels:?}");
        let l = Axis::log(3e-14, 7e-4);
        assert!(l.ticks().iter().all(|t| l.label(*t).contains('e')));
        assert_eq!(l.label(1e-13), "1e-13");
    }

    #[test]
    fn a_short_log_axis_gets_one_two_five_labels() {
        let a = Axis::log(0.005, 0.7);
        let labels: Vec<String> = a.ticks().iter().map(|t| a.label(*t)).collect();
        assert_eq!(
            labels,
            ["0.005", "0.01", "0.02", "0.05", "0.1", "0.2", "0.5"]
        );
        let b = Axis::log(2.1e-7, 3.9e-7);
        let labels: Vec<String> = b.ticks().iter().map(|t| b.label(*t)).collect();
        assert_eq!(
            labels,
            ["2.5e-7", "3.0e-7", "3.5e-7"],
            "linear multiples when the axis spans less than 1..9 x 10^k gives three"
        );
        // the plastic switch bump's resistance at 12 uN: 0.093 .. 0.15 Ohm
        let d = Axis::log(0.093, 0.152);
        let labels: Vec<String> = d.ticks().iter().map(|t| d.label(*t)).collect();
        assert_eq!(labels, ["0.1", "0.11", "0.12", "0.13", "0.14", "0.15"]);
        let c = Axis::log(1.5e-6, 9e-6);
        let labels: Vec<String> = c.ticks().iter().map(|t| c.label(*t)).collect();
        assert_eq!(
            labels,
            ["2e-6", "3e-6", "4e-6", "5e-6", "6e-6", "7e-6", "8e-6", "9e-6"]
        );
    }

    #[test]
    fn symlog_is_linear_near_zero_and_logarithmic_beyond() {
        let a = Axis::fit(-2e-5, 1.3e-2, Some(2e-5));
        assert_eq!(a.scale(), Scale::SymLog(2e-5));
        assert!(a.ticks().contains(&0.0) && a.ticks().contains(&1e-2));
        assert!(a.minor.contains(&3e-3) && a.minor.iter().all(|v| v.abs() >= 2e-5));
        assert!(a.fraction(0.0) > 0.0 && a.fraction(0.0) < 0.3);
        // A decade is nearly the same length beyond c (6 % shorter next
        // to c, where log10(1 + x/c) still bends).
        let d1 = a.fraction(1e-3) - a.fraction(1e-4);
        let d2 = a.fraction(1e-2) - a.fraction(1e-3);
        assert!((d1 - d2).abs() < 0.1 * d2);
        assert_eq!(Axis::fit(-1.0, 2.0, Some(1.0)).scale(), Scale::Linear);
    }
}
