//! The tables of `stancf sweep` read back: an RFC 4180 reader (sweep.csv
//! and extremes.csv quote their cells), a table's header and rows, a
//! column by name.

use std::path::Path;

/// An RFC 4180 reader: fields separated by commas, records by line breaks
/// (CRLF or LF); a quoted field may hold commas, line breaks and quotes
/// (doubled). Panics on a quote inside an unquoted field or an unclosed
/// quote, which a writer without quoting produces.
pub fn read_rfc4180(s: &str) -> Vec<Vec<String>> {
    let mut records = Vec::new();
    let mut record = Vec::new();
    let mut field = String::new();
    let mut chars = s.chars().peekable();
    let mut quoted_field = false;
    while let Some(c) = chars.next() {
        match c {
            '"' if field.is_empty() && !quoted_field => {
                quoted_field = true;
                loop {
                    match chars.next().expect("a quoted field is closed") {
                        '"' if chars.peek() == Some(&'"') => {
                            chars.next();
                            field.push('"');
                        }
                        '"' => break,
                        c => field.push(c),
                    }
                }
                assert!(
                    matches!(chars.peek(), None | Some(',' | '\n' | '\r')),
                    "text after a closing quote in {s:?}"
                );
            }
            '"' => panic!("a quote inside an unquoted field in {s:?}"),
            ',' => {
                record.push(std::mem::take(&mut field));
                quoted_field = false;
            }
            '\r' if chars.peek() == Some(&'\n') => {}
            '\n' => {
                record.push(std::mem::take(&mut field));
                records.push(std::mem::take(&mut record));
                quoted_field = false;
            }
            c => field.push(c),
        }
    }
    if !field.is_empty() || !record.is_empty() {
        record.push(field);
        records.push(record);
    }
    records
}

/// sweep.csv of `dir` as rows of named cells, with its header.
pub fn sweep_table(dir: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    csv_table(&dir.join("sweep.csv"))
}

/// A CSV file as rows of cells, with its header; every row as long.
pub fn csv_table(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let s = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path:?}: {e}"));
    let mut rows = read_rfc4180(&s);
    let header = rows.remove(0);
    for r in &rows {
        assert_eq!(r.len(), header.len(), "{r:?} against {header:?}");
    }
    (header, rows)
}

/// The index of the column `name`.
pub fn column(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}
