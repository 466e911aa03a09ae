//! Reading result files back (docs/interface.md): the plots and the
//! report are drawn from what is on disk.

use std::io;
use std::path::Path;

/// A CSV result file: its header and rows of numbers (an empty field, as
/// in `solver.csv`'s undefined rates, reads as NaN).
#[derive(Clone, Debug)]
pub struct Table {
    pub header: Vec<String>,
    pub rows: Vec<Vec<f64>>,
}

impl Table {
    pub fn read(path: &Path) -> io::Result<Table> {
        let text = crate::input_file::read_result_text(path)?;
        let flat = FlatTable::parse(&text, &path.display().to_string())?;
        let width = flat.header.len().max(1);
        Ok(Table {
            rows: flat.values.chunks(width).map(<[f64]>::to_vec).collect(),
            header: flat.header,
        })
    }

    /// Index of a column.
    pub fn col(&self, name: &str) -> Option<usize> {
        self.header.iter().position(|h| h == name)
    }

    /// Index of a column that must exist.
    pub fn need(&self, name: &str, file: &str) -> io::Result<usize> {
        self.col(name).ok_or_else(|| {
            io::Error::new(
                io::ErrorKind::InvalidData,
                format!("{file}: no column {name:?}"),
            )
        })
    }

    /// The values of a column.
    pub fn column(&self, c: usize) -> Vec<f64> {
        self.rows.iter().map(|r| r[c]).collect()
    }
}

/// A numeric CSV result file parsed whole: its header, its row count and
/// its values row after row. Blank lines are skipped; an empty field
/// reads as NaN; every number is read correctly rounded (as Python's
/// `float` reads it, so `stancf.run`'s arrays from memory are the files'
/// to the bit).
#[derive(Clone, Debug)]
pub struct FlatTable {
    pub header: Vec<String>,
    pub rows: usize,
    pub values: Vec<f64>,
}

impl FlatTable {
    /// Parses `text`; `name` names it in errors (with the row).
    pub fn parse(text: &str, name: &str) -> io::Result<FlatTable> {
        let bad = |row: usize, what: String| {
            io::Error::new(
                io::ErrorKind::InvalidData,
                format!("{name} row {row}: {what}"),
            )
        };
        let mut lines = text.lines().filter(|l| !l.trim().is_empty());
        let header: Vec<String> = lines
            .next()
            .unwrap_or("")
            .trim()
            .split(',')
            .map(|h| h.trim().to_string())
            .collect();
        let mut values = Vec::new();
        let mut rows = 0;
        for (i, line) in lines.enumerate() {
            let start = values.len();
            for field in line.trim().split(',') {
                let field = field.trim();
                values.push(if field.is_empty() {
                    f64::NAN
                } else {
                    field
                        .parse::<f64>()
                        .map_err(|e| bad(i + 2, format!("{field:?}: {e}")))?
                });
            }
            let fields = values.len() - start;
            if fields != header.len() {
                return Err(bad(
                    i + 2,
                    format!("{fields} fields, the header has {}", header.len()),
                ));
            }
            rows += 1;
        }
        Ok(FlatTable {
            header,
            rows,
            values,
        })
    }
}

/// A CSV file with text columns (e.g. the element name): fields as text.
#[derive(Clone, Debug)]
pub struct TextTable {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

impl TextTable {
    pub fn read(path: &Path) -> io::Result<TextTable> {
        let text = crate::input_file::read_result_text(path)?;
        let mut lines = text.lines().filter(|l| !l.trim().is_empty());
        let split = |l: &str| {
            l.split(',')
                .map(|f| f.trim().to_string())
                .collect::<Vec<_>>()
        };
        let header = split(lines.next().unwrap_or(""));
        let rows: Vec<Vec<String>> = lines.map(split).collect();
        if let Some((i, r)) = rows
            .iter()
            .enumerate()
            .find(|(_, r)| r.len() != header.len())
        {
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                format!(
                    "{} row {}: {} fields, the header has {}",
                    path.display(),
                    i + 2,
                    r.len(),
                    header.len()
                ),
            ));
        }
        Ok(TextTable { header, rows })
    }

    pub fn need(&self, name: &str, file: &str) -> io::Result<usize> {
        self.header.iter().position(|h| h == name).ok_or_else(|| {
            io::Error::new(
                io::ErrorKind::InvalidData,
                format!("{file}: no column {name:?}"),
            )
        })
    }

    /// A field as a number (NaN if it is not one).
    pub fn num(row: &[String], col: usize) -> f64 {
        row[col].parse().unwrap_or(f64::NAN)
    }
}

/// The rows of a table grouped by their first column (t), in file order.
pub fn by_time(table: &Table) -> Vec<(f64, Vec<&Vec<f64>>)> {
    let mut out: Vec<(f64, Vec<&Vec<f64>>)> = Vec::new();
    for row in &table.rows {
        match out.last_mut() {
            Some((t, rows)) if *t == row[0] => rows.push(row),
            _ => out.push((row[0], vec![row])),
        }
    }
    out
}

/// `n` indices spread evenly over 0..len, first and last included.
pub fn spread(len: usize, n: usize) -> Vec<usize> {
    if len == 0 {
        return Vec::new();
    }
    if len <= n {
        return (0..len).collect();
    }
    let mut v: Vec<usize> = (0..n)
        .map(|k| ((k as f64) * (len - 1) as f64 / (n - 1) as f64).round() as usize)
        .collect();
    v.dedup();
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_keeps_the_ends() {
        assert_eq!(spread(5, 9), vec![0, 1, 2, 3, 4]);
        assert_eq!(spread(101, 5), vec![0, 25, 50, 75, 100]);
        assert!(spread(0, 3).is_empty());
    }
}
