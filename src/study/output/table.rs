//! The run's tables in memory: the columns of `curve.csv`,
//! `montecarlo.csv` or a sweep's `results.csv` as vectors, for programs
//! (the Python package) that want the numbers without files. Built from the
//! very text the files hold, so both carry the same values bit for bit
//! (every number is written with Rust's shortest round-trip format).

/// One column of a table.
#[derive(Debug, Clone, PartialEq)]
pub enum Column {
    /// Numbers in the column's unit; an empty cell (not computed) is NaN.
    Numbers(Vec<f64>),
    /// Whole numbers (`index`, `seed` of a sweep).
    Integers(Vec<u64>),
    /// Text (`leg`, `note`, a sweep's `status`).
    Text(Vec<String>),
}

/// Columns that hold text.
pub const TEXT_COLUMNS: [&str; 3] = ["leg", "note", "status"];
/// Columns that hold whole numbers.
pub const INTEGER_COLUMNS: [&str; 2] = ["index", "seed"];

/// A table: its columns by header name, in file order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Table {
    /// `(header name, values)`, in the order of the file's header.
    pub columns: Vec<(String, Column)>,
}

impl Table {
    /// The table of a CSV text this crate wrote (a header line, then rows of
    /// plain cells without quotes): [`TEXT_COLUMNS`] as text,
    /// [`INTEGER_COLUMNS`] as whole numbers (0 where empty), every other
    /// column as numbers (NaN where empty or not a number).
    pub fn from_csv(text: &str) -> Table {
        let mut lines = text.lines().filter(|l| !l.is_empty());
        let names: Vec<&str> = lines.next().map_or(Vec::new(), |h| h.split(',').collect());
        let mut columns: Vec<(String, Column)> = names
            .iter()
            .map(|&n| {
                let col = if TEXT_COLUMNS.contains(&n) {
                    Column::Text(Vec::new())
                } else if INTEGER_COLUMNS.contains(&n) {
                    Column::Integers(Vec::new())
                } else {
                    Column::Numbers(Vec::new())
                };
                (n.to_string(), col)
            })
            .collect();
        for line in lines {
            let mut cells = line.split(',');
            for (_, col) in columns.iter_mut() {
                let cell = cells.next().unwrap_or("");
                match col {
                    Column::Text(v) => v.push(cell.to_string()),
                    Column::Integers(v) => v.push(cell.parse().unwrap_or(0)),
                    Column::Numbers(v) => v.push(cell.parse().unwrap_or(f64::NAN)),
                }
            }
        }
        Table { columns }
    }

    /// The column named `name`.
    pub fn get(&self, name: &str) -> Option<&Column> {
        self.columns.iter().find(|(n, _)| n == name).map(|(_, c)| c)
    }

    /// Rows in the table.
    pub fn rows(&self) -> usize {
        self.columns.first().map_or(0, |(_, c)| match c {
            Column::Numbers(v) => v.len(),
            Column::Integers(v) => v.len(),
            Column::Text(v) => v.len(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_by_kind_with_empty_cells() {
        let t = Table::from_csv("leg,separation_m,load_N\napproach,1e-8,\nretract,5e-9,-2.5e-3\n");
        assert_eq!(t.rows(), 2);
        assert_eq!(
            t.get("leg"),
            Some(&Column::Text(vec!["approach".into(), "retract".into()]))
        );
        let Some(Column::Numbers(load)) = t.get("load_N") else {
            panic!("load_N is numbers")
        };
        assert!(load[0].is_nan());
        assert_eq!(load[1], -2.5e-3);
    }
}
