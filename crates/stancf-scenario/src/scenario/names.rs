//! Where a system's values were written, so that a refusal names them as
//! the user wrote them: TOML keys (`line_types[0].diameter`) for a
//! system scenario, the deck's line and column (`line 7: Diam`) for the
//! values a MoorDyn deck gives, and the `[[mesh]]` entry that remeshed a
//! deck's line.

use crate::moordyn::{Deck, OptionKind, SupportedOption};

/// The names of a system's values (see the module documentation).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Names {
    /// The deck the line types, points, lines and options come from
    /// (None: a TOML system, every value under its key).
    deck: Option<Box<DeckNames>>,
    /// The parts rods add (boxed: most systems have none).
    rods: Box<RodNames>,
}

/// The bodies and points rods add.
#[derive(Clone, Debug, Default, PartialEq)]
struct RodNames {
    /// The bodies of free rods: (body index, rod index).
    bodies: Vec<(usize, usize)>,
    /// A deck's points at rod ends: (point index, rod index).
    points: Vec<(usize, usize)>,
    /// The points a host moves for CoupledPinned bodies: (point index,
    /// body index).
    host_pins: Vec<(usize, usize)>,
}

/// The lines of a deck's rows and options.
#[derive(Clone, Debug, PartialEq)]
struct DeckNames {
    /// The deck as messages name it; None when it is the file the
    /// messages are about (a deck run alone).
    file: Option<String>,
    line_types: Vec<usize>,
    bodies: Vec<usize>,
    rod_types: Vec<usize>,
    rods: Vec<usize>,
    points: Vec<usize>,
    lines: Vec<usize>,
    options: Vec<(SupportedOption, String, usize)>,
    /// The `[[mesh]]` entry that remeshed each line, if any.
    meshes: Vec<Option<usize>>,
}

impl Names {
    /// The names of the values of `deck`; `file` names the deck when the
    /// messages are about another file (a scenario that takes the deck).
    pub fn of_deck(deck: &Deck, file: Option<String>) -> Names {
        Names {
            deck: Some(Box::new(DeckNames {
                file,
                line_types: deck.line_types.iter().map(|t| t.line).collect(),
                bodies: deck.bodies.iter().map(|b| b.line).collect(),
                rod_types: deck.rod_types.iter().map(|t| t.line).collect(),
                rods: deck.rods.iter().map(|r| r.line).collect(),
                points: deck.points.iter().map(|p| p.line).collect(),
                lines: deck.lines.iter().map(|l| l.line).collect(),
                options: deck
                    .options
                    .iter()
                    .filter_map(|o| match o.kind {
                        OptionKind::Supported(s) => Some((s, o.name.clone(), o.line)),
                        _ => None,
                    })
                    .collect(),
                meshes: vec![None; deck.lines.len()],
            })),
            ..Names::default()
        }
    }

    /// The names of the parts rods add: a free rod's body is named by the
    /// rod (`rods[k].end_a` for its position, `rods[k].rod_type` for the
    /// rest; a deck's rod's line), a point from `first_point` on at a
    /// rod's end by the rod.
    pub fn with_rods(mut self, rods: &[super::rod_parts::SystemRod], first_point: usize) -> Names {
        for (k, r) in rods.iter().enumerate() {
            if let Some(body) = r.own_body() {
                self.rods.bodies.push((body, k));
            }
            for p in r.points.iter().flatten().filter(|p| **p >= first_point) {
                self.rods.points.push((*p, k));
            }
        }
        self
    }

    /// The name of rod k's value: `position` is its end A, the rest its
    /// type.
    pub fn rod(&self, k: usize, key: &str) -> String {
        let (key, column) = match key {
            "position" => ("end_a", "Xa, Ya, Za"),
            _ => ("rod_type", "RodType"),
        };
        match &self.deck {
            Some(d) => d.at(d.rods[k], column),
            None => format!("rods[{k}].{key}"),
        }
    }

    /// Line i of a deck was remeshed by `[[mesh]]` entry `entry`: its
    /// elements are named `mesh[entry].elements` from now on.
    pub fn remeshed(&mut self, line: usize, entry: usize) {
        if let Some(d) = self.deck.as_mut() {
            d.meshes[line] = Some(entry);
        }
    }

    /// Whether the values come from a deck.
    pub fn is_deck(&self) -> bool {
        self.deck.is_some()
    }

    /// `key` of rod type i (`rod_types[i].<key>`), or its `column` in
    /// the deck.
    pub fn rod_type(&self, i: usize, key: &str, column: &str) -> String {
        match &self.deck {
            Some(d) => d.at(d.rod_types[i], column),
            None => format!("rod_types[{i}].{key}"),
        }
    }

    /// Rod k: `rods[k]`, or its deck line (`line 12: rod 1`).
    pub fn rod_place(&self, k: usize) -> String {
        match &self.deck {
            Some(d) => d.at(d.rods[k], &format!("rod {}", k + 1)),
            None => format!("rods[{k}]"),
        }
    }

    /// `key` of rod k (`rods[k].<key>`), or its `column` in the deck.
    pub fn rod_key(&self, k: usize, key: &str, column: &str) -> String {
        match &self.deck {
            Some(d) => d.at(d.rods[k], column),
            None => format!("rods[{k}].{key}"),
        }
    }

    /// `key` of line type i (`line_types[i].<key>`), or its `column` in
    /// the deck.
    pub fn line_type(&self, i: usize, key: &str, column: &str) -> String {
        match &self.deck {
            Some(d) => d.at(d.line_types[i], column),
            None => format!("line_types[{i}].{key}"),
        }
    }

    /// `key` of body i (`bodies[i].<key>`), or its `column` in the deck.
    pub fn body(&self, i: usize, key: &str, column: &str) -> String {
        if let Some(&(_, k)) = self.rods.bodies.iter().find(|(b, _)| *b == i) {
            return self.rod(k, key);
        }
        match &self.deck {
            // After the deck's bodies, a farm's turbines (super::farm).
            Some(d) => match d.bodies.get(i) {
                Some(&line) => d.at(line, column),
                None => format!("turbine {} ({key})", i - d.bodies.len() + 1),
            },
            None => format!("bodies[{i}].{key}"),
        }
    }

    /// The names of the points made for CoupledPinned bodies: their
    /// bodies' (`bodies[b].host_pin` indices).
    pub fn with_host_pins(mut self, bodies: &[super::SystemBody]) -> Names {
        for (b, body) in bodies.iter().enumerate() {
            if let Some(p) = body.host_pin {
                self.rods.host_pins.push((p, b));
            }
        }
        self
    }

    /// `key` of point i, or its `column` in the deck.
    pub fn point(&self, i: usize, key: &str, column: &str) -> String {
        if let Some(&(_, k)) = self.rods.points.iter().find(|(p, _)| *p == i) {
            return self.rod(k, key);
        }
        if let Some(&(_, b)) = self.rods.host_pins.iter().find(|(p, _)| *p == i) {
            return self.body(b, "position", "X0, Y0, Z0");
        }
        match &self.deck {
            Some(d) => d.at(d.points[i], column),
            None => format!("points[{i}].{key}"),
        }
    }

    /// The key of an error of the library (`bodies[i]`, `lines[i]` or
    /// `points[i]`, and what follows) as the deck names the object: its
    /// row and the object (`line 14: rod 1`; a free rod's body is its
    /// rod, a rod end's point its rod). A TOML system's keys, and keys of
    /// other objects, are the library's.
    pub fn library_key(&self, key: &str) -> String {
        let Some(d) = &self.deck else {
            return key.to_string();
        };
        let index = |prefix: &str| {
            let r = key.strip_prefix(prefix)?;
            let end = r.find(']')?;
            Some((r[..end].parse::<usize>().ok()?, &r[end + 1..]))
        };
        let rod =
            |k: usize, rest: &str| format!("{}{rest}", d.at(d.rods[k], &format!("rod {}", k + 1)));
        if let Some((i, rest)) = index("bodies[") {
            if let Some(&(_, k)) = self.rods.bodies.iter().find(|(b, _)| *b == i) {
                return rod(k, rest);
            }
            if let Some(&line) = d.bodies.get(i) {
                return format!("{}{rest}", d.at(line, &format!("body {}", i + 1)));
            }
        }
        if let Some((i, rest)) = index("points[") {
            if let Some(&(_, k)) = self.rods.points.iter().find(|(p, _)| *p == i) {
                return rod(k, rest);
            }
            if let Some(&line) = d.points.get(i) {
                return format!("{}{rest}", d.at(line, &format!("point {}", i + 1)));
            }
        }
        if let Some((i, rest)) = index("lines[") {
            if let Some(&line) = d.lines.get(i) {
                return format!("{}{rest}", d.at(line, &format!("line {}", i + 1)));
            }
        }
        key.to_string()
    }

    /// `key` of line i, or its `column` in the deck; a remeshed deck
    /// line's elements are its `[[mesh]]` entry's.
    pub fn line(&self, i: usize, key: &str, column: &str) -> String {
        match &self.deck {
            Some(d) => match d.meshes[i] {
                Some(entry) if key == "elements" => format!("mesh[{entry}].elements"),
                _ => d.at(d.lines[i], column),
            },
            None => format!("lines[{i}].{key}"),
        }
    }

    /// The scenario key `key`, or the deck's option `which` where the
    /// deck gives it (its name as written).
    pub fn option(&self, key: &str, which: SupportedOption) -> String {
        let given = self.deck.as_ref().and_then(|d| {
            d.options
                .iter()
                .find(|(s, ..)| *s == which)
                .map(|(_, name, line)| d.at(*line, name))
        });
        given.unwrap_or_else(|| key.to_string())
    }
}

impl DeckNames {
    /// "line 7: Diam", with the deck's name before it when the messages
    /// are about another file.
    fn at(&self, line: usize, column: &str) -> String {
        match &self.file {
            Some(f) => format!("{f} line {line}: {column}"),
            None => format!("line {line}: {column}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DECK: &str = "--- LINE TYPES ---\n\
        TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n\
        (-) (m) (kg/m) (N) (Ns) (Nm2) (-) (-) (-) (-)\n\
        rope 0.01 0.08 2e4 0 0 0 0 0 0\n\
        --- POINTS ---\n\
        ID Attachment X Y Z Mass Volume CdA Ca\n\
        (#) (-) (m) (m) (m) (kg) (m3) (m2) (-)\n\
        1 Fixed 0 0 -1 0 0 0 0\n\
        2 Coupled 1 0 -1 0 0 0 0\n\
        --- LINES ---\n\
        ID LineType AttachA AttachB UnstrLen NumSegs Outputs\n\
        (#) (-) (#) (#) (m) (-) (-)\n\
        1 rope 1 2 1.0 4 -\n\
        --- OPTIONS ---\n\
        50 WtrDpth\n\
        1025 rho\n\
        --- END ---\n";

    #[test]
    fn deck_values_are_named_by_their_line_and_column_and_toml_values_by_key() {
        let deck = crate::moordyn::parse(DECK).unwrap();
        let mut n = Names::of_deck(&deck, None);
        assert_eq!(n.line_type(0, "diameter", "Diam"), "line 4: Diam");
        assert_eq!(n.point(1, "mass", "Mass"), "line 9: Mass");
        assert_eq!(n.line(0, "length", "UnstrLen"), "line 13: UnstrLen");
        assert_eq!(
            n.option("water.density", SupportedOption::WaterDensity),
            "line 16: rho"
        );
        assert_eq!(
            n.option("water.seabed.stiffness", SupportedOption::BottomStiffness),
            "water.seabed.stiffness"
        );
        n.remeshed(0, 2);
        assert_eq!(n.line(0, "elements", "NumSegs"), "mesh[2].elements");
        let named = Names::of_deck(&deck, Some("deck.txt".into()));
        assert_eq!(
            named.line(0, "length", "UnstrLen"),
            "deck.txt line 13: UnstrLen"
        );
        let toml = Names::default();
        assert_eq!(toml.line(0, "elements", "NumSegs"), "lines[0].elements");
        assert_eq!(toml.point(2, "mass", "Mass"), "points[2].mass");
    }

    /// The library's keys of a deck's objects become their rows; others,
    /// and a TOML system's, stay as they are.
    #[test]
    fn the_librarys_keys_name_the_decks_rows() {
        let deck = crate::moordyn::parse(DECK).unwrap();
        let n = Names::of_deck(&deck, None);
        assert_eq!(n.library_key("points[1]"), "line 9: point 2");
        assert_eq!(n.library_key("lines[0].length"), "line 13: line 1.length");
        assert_eq!(n.library_key("points[7]"), "points[7]");
        assert_eq!(n.library_key("water.depth"), "water.depth");
        assert_eq!(Names::default().library_key("bodies[0]"), "bodies[0]");
    }
}
