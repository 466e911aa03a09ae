//! A deck cut into its title and sections, each section a list of rows
//! of words, as MoorDyn-C's `findStartOfSection` and `str::split` see
//! them.

use super::DeckError;

/// The sections MoorDyn v2 knows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SectionKind {
    LineTypes,
    RodTypes,
    Bodies,
    Rods,
    Points,
    Lines,
    Failure,
    Control,
    ExternalLoads,
    SyropeIc,
    Options,
    Outputs,
}

const ALL: [SectionKind; 12] = [
    SectionKind::LineTypes,
    SectionKind::RodTypes,
    SectionKind::Bodies,
    SectionKind::Rods,
    SectionKind::Points,
    SectionKind::Lines,
    SectionKind::Failure,
    SectionKind::Control,
    SectionKind::ExternalLoads,
    SectionKind::SyropeIc,
    SectionKind::Options,
    SectionKind::Outputs,
];

impl SectionKind {
    /// The key phrases of `MoorDyn2.cpp`'s `findStartOfSection` calls
    /// (`CONTROL` and `EXTERNAL LOADS` are MoorDyn-F's).
    fn keywords(self) -> &'static [&'static str] {
        match self {
            SectionKind::LineTypes => &["LINE DICTIONARY", "LINE TYPES"],
            SectionKind::RodTypes => &["ROD DICTIONARY", "ROD TYPES"],
            SectionKind::Bodies => &["BODIES", "BODY LIST", "BODY PROPERTIES"],
            SectionKind::Rods => &["RODS", "ROD LIST", "ROD PROPERTIES"],
            SectionKind::Points => &[
                "POINTS",
                "POINT LIST",
                "POINT PROPERTIES",
                "CONNECTION PROPERTIES",
                "NODE PROPERTIES",
            ],
            SectionKind::Lines => &["LINES", "LINE LIST", "LINE PROPERTIES"],
            SectionKind::Failure => &["FAILURE"],
            SectionKind::Control => &["CONTROL"],
            SectionKind::ExternalLoads => &["EXTERNAL LOADS"],
            SectionKind::SyropeIc => &["SYROPE IC"],
            SectionKind::Options => &["OPTIONS"],
            SectionKind::Outputs => &["OUTPUT"],
        }
    }

    /// The usual name of the section, for messages.
    pub(crate) fn title(self) -> &'static str {
        match self {
            SectionKind::LineTypes => "LINE TYPES",
            SectionKind::RodTypes => "ROD TYPES",
            SectionKind::Bodies => "BODIES",
            SectionKind::Rods => "RODS",
            SectionKind::Points => "POINTS",
            SectionKind::Lines => "LINES",
            SectionKind::Failure => "FAILURE",
            SectionKind::Control => "CONTROL",
            SectionKind::ExternalLoads => "EXTERNAL LOADS",
            SectionKind::SyropeIc => "SYROPE IC",
            SectionKind::Options => "OPTIONS",
            SectionKind::Outputs => "OUTPUTS",
        }
    }

    /// Whether the section starts with rows of column names and units
    /// (all but `OPTIONS` and `OUTPUTS`, which `findStartOfSection`
    /// enters right after the header).
    fn is_table(self) -> bool {
        !matches!(self, SectionKind::Options | SectionKind::Outputs)
    }

    /// The sections whose key phrases a line of text contains (upper-cased,
    /// as MoorDyn compares); the caller checks for `---`.
    fn matching(text: &str) -> Vec<SectionKind> {
        let upper = text.to_ascii_uppercase();
        ALL.into_iter()
            .filter(|k| k.keywords().iter().any(|w| upper.contains(w)))
            .collect()
    }

    /// The section a header line names, if it names one.
    pub(crate) fn of_header(text: &str) -> Option<SectionKind> {
        SectionKind::matching(text).first().copied()
    }
}

/// A non-blank line of a section: its words up to the first comment.
#[derive(Debug)]
pub(crate) struct Row<'a> {
    /// 1-based line number.
    pub(crate) line: usize,
    /// The line as written.
    pub(crate) raw: &'a str,
    /// The words, at least one (once [`split`] has returned).
    pub(crate) words: Vec<&'a str>,
}

/// A section: its header line and its data rows (for tables, the rows of
/// column names and units are taken off).
#[derive(Debug)]
pub(crate) struct Section<'a> {
    pub(crate) kind: SectionKind,
    pub(crate) header: usize,
    pub(crate) rows: Vec<Row<'a>>,
}

/// A deck's title and sections in file order.
#[derive(Debug)]
pub(crate) struct Layout<'a> {
    pub(crate) title: String,
    pub(crate) sections: Vec<Section<'a>>,
}

/// The words of a line as MoorDyn's `str::split` gives them: separated
/// by blanks (MoorDyn splits on spaces only; tabs are accepted here too),
/// ending before the first word that contains `#`.
pub(crate) fn words(text: &str) -> Vec<&str> {
    text.split_whitespace()
        .take_while(|w| !w.contains('#'))
        .collect()
}

/// Where the rows being read go.
enum Target {
    Title,
    Section(usize),
    /// After a line of dashes naming no section (an end marker such as
    /// `--- END ---`), at this line: no rows may follow it.
    Marker(usize, String),
}

/// The lines of a deck ([`crate::echo::text_lines`]: some MoorDyn decks
/// still carry the lone `\r` line ends of classic Mac OS).
pub(crate) fn deck_lines(text: &str) -> impl Iterator<Item = &str> {
    crate::echo::text_lines(text)
}

/// Cuts a deck into title and sections. A line containing `---` naming
/// no section ends the current section; rows after it (before the next
/// header) make it an unknown section header. Before the first section
/// such a line and the rows after it belong to the title (MoorDyn looks
/// for its sections by name and reads past the rest).
pub(crate) fn split(text: &str) -> Result<Layout<'_>, DeckError> {
    let mut title: Vec<&str> = Vec::new();
    let mut sections: Vec<Section> = Vec::new();
    let mut target = Target::Title;
    let mut seen_content = false;
    for (i, raw) in deck_lines(text).enumerate() {
        let line = i + 1;
        if raw.contains("---") {
            target = header(raw, line, seen_content, &mut sections)?;
            seen_content = true;
            continue;
        }
        let w = words(raw);
        match &target {
            Target::Title => {
                if !raw.trim().is_empty() {
                    title.push(raw.trim());
                    seen_content = true;
                }
            }
            _ if raw.trim().is_empty() => {}
            Target::Section(s) => sections[*s].rows.push(Row {
                line,
                raw,
                words: w,
            }),
            Target::Marker(..) if w.is_empty() => {}
            Target::Marker(at, text) => {
                return Err(DeckError::at(
                    *at,
                    format!(
                        "unknown section header \"{text}\" (rows follow it from line {line}); \
                         known sections: {}",
                        known_sections()
                    ),
                ))
            }
        }
    }
    for s in &mut sections {
        if s.kind.is_table() {
            strip_column_rows(s)?;
        }
        s.rows.retain(|r| !r.words.is_empty());
    }
    Ok(Layout {
        title: title.join("\n"),
        sections,
    })
}

fn known_sections() -> String {
    ALL.iter().map(|k| k.title()).collect::<Vec<_>>().join(", ")
}

/// The target of the rows after a line containing `---`.
fn header(
    raw: &str,
    line: usize,
    seen_content: bool,
    sections: &mut Vec<Section>,
) -> Result<Target, DeckError> {
    let kinds = SectionKind::matching(raw);
    let text = raw.trim().to_string();
    match kinds.as_slice() {
        // Before the first section, MoorDyn reads past any line: a dashed
        // line there (a banner, a dashed title) and what follows it are
        // the deck's title.
        [] if !seen_content || sections.is_empty() => Ok(Target::Title),
        [] => Ok(Target::Marker(line, text)),
        [kind] => {
            if let Some(first) = sections.iter().find(|s| s.kind == *kind) {
                return Err(DeckError::at(
                    line,
                    format!(
                        "a second {} section (the first starts at line {}); \
                         MoorDyn reads only the first",
                        kind.title(),
                        first.header
                    ),
                ));
            }
            sections.push(Section {
                kind: *kind,
                header: line,
                rows: Vec::new(),
            });
            Ok(Target::Section(sections.len() - 1))
        }
        several => {
            let names: Vec<&str> = several.iter().map(|k| k.title()).collect();
            Err(DeckError::at(
                line,
                format!(
                    "the header \"{text}\" names several sections ({}); MoorDyn would read \
                     it as each of them",
                    names.join(", ")
                ),
            ))
        }
    }
}

/// Takes off a table's rows of column names and units (whole lines: a
/// units row such as `(#) (m)` holds a `#`). MoorDyn skips
/// exactly the two lines after the header whatever they hold; here the
/// first two non-blank rows are taken off and the second must look like
/// units (start with `(`), so that a missing units row does not silently
/// swallow the first data row. A table with no rows at all is empty.
fn strip_column_rows(s: &mut Section) -> Result<(), DeckError> {
    if s.rows.is_empty() {
        return Ok(());
    }
    let title = s.kind.title();
    if s.rows.len() < 2 {
        return Err(DeckError::at(
            s.rows[0].line,
            format!(
                "{title} needs a row of column names and a row of units \
                 (in parentheses) before its data rows"
            ),
        ));
    }
    let units = &s.rows[1];
    if !units.raw.trim_start().starts_with('(') {
        return Err(DeckError::at(
            units.line,
            format!(
                "expected the row of units of {title} (e.g. \"(m)\", in parentheses) after \
                 its row of column names, found \"{}\"; MoorDyn skips the two lines after a \
                 table's header",
                units.raw.trim()
            ),
        ));
    }
    s.rows.drain(..2);
    Ok(())
}
