//! The CPU time this process has used: what a user waits for on a shared
//! machine (wall time counts the other users' work too).

/// User + system CPU time (s) of this process so far, from
/// `/proc/self/stat` (fields 14 and 15, in the kernel's USER_HZ = 100
/// ticks per second); `None` where it cannot be read (not Linux).
pub fn process_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command name (which may hold spaces) in parentheses.
    let rest = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grows_with_work() {
        let Some(t0) = process_cpu_seconds() else {
            return; // not Linux
        };
        let mut x = 0.0f64;
        let start = std::time::Instant::now();
        while start.elapsed().as_secs_f64() < 0.05 {
            x += x.sin() + 1.0;
        }
        assert!(x > 0.0);
        let t1 = process_cpu_seconds().unwrap();
        assert!(t1 >= t0 && t1 < t0 + 60.0, "{t0} {t1}");
    }
}
