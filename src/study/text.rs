//! Small text helpers shared by the command line and the bindings.

/// Levenshtein distance between `a` and `b` (characters): the fewest
/// insertions, deletions and substitutions that turn one into the other.
///
/// ```
/// use asperity::study::text::edit_distance;
/// assert_eq!(edit_distance("sigmaa", "sigma"), 1);
/// assert_eq!(edit_distance("rn", "run"), 1);
/// assert_eq!(edit_distance("", "abc"), 3);
/// ```
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}
