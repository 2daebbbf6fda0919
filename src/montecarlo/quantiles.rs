//! Distribution-free intervals of a quantile: the order statistics of a
//! sample whose ranks come from the exact binomial distribution of the
//! count of values below the quantile (David & Nagaraja 2003, sec. 7.1).

/// A pair of ranks `1 <= lower < upper <= n` of a sample's order
/// statistics and the exact probability that they enclose the true
/// `q`-quantile of a continuous distribution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RankInterval {
    /// Rank (1-based, ascending) of the lower end.
    pub lower: usize,
    /// Rank of the upper end.
    pub upper: usize,
    /// `P(X_(lower) <= xi_q <= X_(upper)) = sum_{k = lower}^{upper - 1}
    /// C(n, k) q^k (1 - q)^(n - k)`: the count `B ~ Bin(n, q)` of values
    /// below the quantile lies in `[lower, upper - 1]` (David & Nagaraja
    /// 2003, sec. 7.1; Conover 1999, sec. 3.2).
    pub coverage: f64,
}

/// An order-statistic interval of a quantile of the pull-offs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuantileInterval {
    /// Its ends (N): the order statistics of `ranks`.
    pub bounds: (f64, f64),
    /// The ranks and their exact coverage.
    pub ranks: RankInterval,
}

/// The binomial probabilities `C(n, k) q^k (1 - q)^(n - k)`, `k = 0..=n`,
/// by the ratio recurrence both ways from the mode (set to 1) and then
/// normalised by their sum, so nothing underflows near the mode and the
/// relative error is a few `n` ulps.
fn binomial_pmf(n: usize, q: f64) -> Vec<f64> {
    let mut p = vec![0.0; n + 1];
    if q <= 0.0 {
        p[0] = 1.0;
        return p;
    }
    if q >= 1.0 {
        p[n] = 1.0;
        return p;
    }
    let mode = (((n + 1) as f64 * q).floor() as usize).min(n);
    let odds = q / (1.0 - q);
    p[mode] = 1.0;
    for k in mode..n {
        // p(k + 1) = p(k) (n - k)/(k + 1) q/(1 - q)
        p[k + 1] = p[k] * (n - k) as f64 / (k + 1) as f64 * odds;
    }
    for k in (0..mode).rev() {
        // p(k) = p(k + 1) (k + 1)/(n - k) (1 - q)/q
        p[k] = p[k + 1] * (k + 1) as f64 / (n - k) as f64 / odds;
    }
    let total: f64 = p.iter().sum();
    p.iter_mut().for_each(|v| *v /= total);
    p
}

/// The shortest pair of ranks (`upper - lower` least; of equal lengths the
/// largest coverage, then the lowest ranks) of a sample of `n` whose
/// order statistics enclose the true `q`-quantile (`q` in `(0, 1)`) with
/// exact probability at least `level` ([`RankInterval::coverage`]); `None`
/// when no pair reaches it (fewer than 2 values, or the widest pair's
/// [`widest_coverage`] below `level`: `n = 5` and `q = 0.05` give 0.226).
pub fn quantile_ranks(n: usize, q: f64, level: f64) -> Option<RankInterval> {
    if n < 2 || !(q > 0.0 && q < 1.0) || widest_coverage(n, q) < level {
        return None;
    }
    let pmf = binomial_pmf(n, q);
    // cum[k] = P(B < k)
    let mut cum = vec![0.0; n + 2];
    for k in 0..=n {
        cum[k + 1] = cum[k] + pmf[k];
    }
    // P(lower <= B <= upper - 1), summed directly where short.
    let coverage = |lower: usize, upper: usize| -> f64 {
        if upper - lower <= 64 {
            pmf[lower..upper].iter().sum()
        } else {
            cum[upper] - cum[lower]
        }
    };
    for width in 1..n {
        let best = (1..=n - width)
            .map(|lower| RankInterval {
                lower,
                upper: lower + width,
                coverage: coverage(lower, lower + width),
            })
            .fold(None::<RankInterval>, |b, r| match b {
                Some(b) if b.coverage >= r.coverage => Some(b),
                _ => Some(r),
            });
        if let Some(b) = best.filter(|b| b.coverage >= level) {
            return Some(b);
        }
    }
    None
}

/// The exact coverage of the widest pair of ranks, the sample's minimum
/// and maximum, for the `q`-quantile of `n` values:
/// `1 - (1 - q)^n - q^n` (0 for fewer than 2 values).
pub fn widest_coverage(n: usize, q: f64) -> f64 {
    if n < 2 {
        return 0.0;
    }
    1.0 - (1.0 - q).powf(n as f64) - q.powf(n as f64)
}
