//! MoorDyn's driver input file (OpenFAST's `MoorDyn_Driver`, the
//! `md_driver.inp` or `*.dvr` of OpenFAST's MoorDyn regression tests): the
//! sea a host would give, the deck to run, how long and at what coupling
//! step, and the coupled objects' motions (held, or a time series from a
//! file). Read as `MoorDyn_Driver.f90`'s `ReadDriverInputFile` reads it:
//! line by line in a fixed order, the value first on its line
//! (docs/interface.md, "MoorDyn driver files"):
//!
//! ```text
//! 2 header lines (older drivers then an Echo flag, skipped), a section line
//! Gravity   rhoW   WtrDpth            (one value a line)
//! a section line
//! MDInputFile   OutRootName   TMax   dtC   InputsMode   InputsFile   NumTurbines
//! a section line, table header lines
//! max(1, NumTurbines) rows: ref_X ref_Y surge sway heave roll pitch yaw
//! ```
//!
//! Each value's line must also carry the value's name as its second word
//! (any case, MoorDyn-F's spellings: `WtrDepth`, `InputsMod`), so that a
//! file of another layout is refused naming the line rather than read
//! into the wrong quantity. Turning the file into a run is the
//! scenario's (`scenario::moordyn_driver`).

use std::fmt;

/// A MoorDyn driver input file, read (not yet checked against its deck).
#[derive(Debug, Clone, PartialEq)]
pub struct DriverFile {
    /// m/s^2.
    pub gravity: f64,
    /// kg/m^3.
    pub water_density: f64,
    /// m.
    pub water_depth: f64,
    /// The MoorDyn deck, as written (relative to the driver file's folder
    /// unless absolute, as the driver resolves it).
    pub deck: String,
    /// The prefix of MoorDyn-F's output files (`<root>.MD.out`).
    pub out_root: String,
    /// The run's length (s).
    pub t_max: f64,
    /// The coupling step (s): the interval at which the driver passes the
    /// coupled objects' motions.
    pub dt_c: f64,
    /// 0: the coupled objects held where the deck puts them; 1: their
    /// motions from `inputs_file`.
    pub inputs_mode: i64,
    /// The motions' file (InputsMode 1), as written.
    pub inputs_file: String,
    /// FAST.Farm's turbine count; 0 is OpenFAST's single platform.
    pub turbines: i64,
    /// Per platform: ref_X, ref_Y (m), surge, sway, heave (m), roll,
    /// pitch, yaw (degrees: the driver multiplies them by D2R).
    pub platforms: Vec<[f64; 8]>,
    /// The 1-based line of each value, for messages: gravity, density,
    /// depth, deck, root, TMax, dtC, mode, inputs file, turbines, then the
    /// first platform row.
    pub lines: [usize; 11],
}

/// A driver file that cannot be read: the 1-based line and what is wrong.
#[derive(Debug, Clone, PartialEq)]
pub struct DriverError {
    pub line: usize,
    pub message: String,
}

impl fmt::Display for DriverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

/// The values in the driver's order: (the names accepted as the line's
/// second word, lower-cased; what it is, for messages).
const VALUES: [(&[&str], &str); 10] = [
    (&["gravity", "g"], "Gravity, the gravity (m/s^2)"),
    (&["rhow", "wtrdnsty"], "rhoW, the water density (kg/m^3)"),
    (&["wtrdpth", "wtrdepth"], "WtrDpth, the water depth (m)"),
    (&["mdinputfile"], "MDInputFile, the MoorDyn input file"),
    (&["outrootname"], "OutRootName, the output files' root"),
    (&["tmax"], "TMax, the run's length (s)"),
    (&["dtc"], "dtC, the coupling step (s)"),
    (&["inputsmode", "inputsmod"], "InputsMode, 0 or 1"),
    (&["inputsfile"], "InputsFile, the motions' file"),
    (&["numturbines"], "NumTurbines, 0 or the turbine count"),
];

/// Whether `text` is a MoorDyn driver input file: a line whose second
/// word is `MDInputFile`.
pub fn looks_like_driver(text: &str) -> bool {
    text.lines().any(|l| {
        words(l)
            .get(1)
            .is_some_and(|w| w.eq_ignore_ascii_case("mdinputfile"))
    })
}

/// Reads a driver file (see the module's layout). Refused naming the
/// line: a missing value or a line whose second word is not the value's
/// name, a number that is not finite, a negative or zero gravity,
/// density, depth, TMax or dtC, an InputsMode other than 0 or 1 (the
/// driver's own check), a negative NumTurbines, a platform row of other
/// than 8 numbers.
pub fn parse_driver(text: &str) -> Result<DriverFile, DriverError> {
    let rows: Vec<&str> = text.lines().collect();
    let (values, at) = read_values(&rows)?;
    let number = |k: usize| -> Result<f64, DriverError> {
        let (v, line) = &values[k];
        v.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| DriverError {
                line: *line,
                message: format!("{}: {v:?} is not a finite number", VALUES[k].1),
            })
    };
    let positive = |k: usize| -> Result<f64, DriverError> {
        let x = number(k)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(DriverError {
                line: values[k].1,
                message: format!("{}: {x} must be positive", VALUES[k].1),
            })
        }
    };
    let integer = |k: usize| -> Result<i64, DriverError> {
        let x = number(k)?;
        if x.fract() == 0.0 && x.abs() < 1e9 {
            Ok(x as i64)
        } else {
            Err(DriverError {
                line: values[k].1,
                message: format!("{}: {x} is not a whole number", VALUES[k].1),
            })
        }
    };
    let inputs_mode = integer(7)?;
    if !(0..=1).contains(&inputs_mode) {
        return Err(DriverError {
            line: values[7].1,
            message: format!(
                "InputsMode {inputs_mode}: MoorDyn's driver takes 0 (the coupled objects held) \
                 or 1 (their motions from InputsFile)"
            ),
        });
    }
    let turbines = integer(9)?;
    if turbines < 0 {
        return Err(DriverError {
            line: values[9].1,
            message: format!("NumTurbines {turbines} is negative"),
        });
    }
    let (platforms, first_platform) = read_platforms(&rows, at, turbines)?;
    let text_value = |k: usize| values[k].0.clone();
    let mut lines = [0; 11];
    for (k, (_, line)) in values.iter().enumerate() {
        lines[k] = *line;
    }
    lines[10] = first_platform;
    Ok(DriverFile {
        gravity: positive(0)?,
        water_density: positive(1)?,
        water_depth: positive(2)?,
        deck: text_value(3),
        out_root: text_value(4),
        t_max: positive(5)?,
        dt_c: positive(6)?,
        inputs_mode,
        inputs_file: text_value(8),
        turbines,
        platforms,
        lines,
    })
}

/// The driver's values in their order: each one's word and 1-based
/// line, and the index of the row after the last.
fn read_values(rows: &[&str]) -> Result<(Vec<(String, usize)>, usize), DriverError> {
    let mut at = 2; // the 2 header lines
    let mut values: Vec<(String, usize)> = Vec::with_capacity(VALUES.len());
    for (names, what) in VALUES.iter() {
        // Section lines, and the Echo flag of older drivers, between values.
        while rows.get(at).is_some_and(|r| {
            r.contains("---")
                || words(r)
                    .get(1)
                    .is_some_and(|w| w.eq_ignore_ascii_case("echo"))
        }) {
            at += 1;
        }
        let line = at + 1;
        let row = rows.get(at).ok_or_else(|| DriverError {
            line,
            message: format!("the file ends where {what} is expected"),
        })?;
        let w = words(row);
        let named = w
            .get(1)
            .is_some_and(|n| names.iter().any(|m| n.eq_ignore_ascii_case(m)));
        if !named {
            return Err(DriverError {
                line,
                message: format!(
                    "expected {what}: its value, then its name (MoorDyn's driver reads its \
                     values in a fixed order), found {:?}",
                    row.trim()
                ),
            });
        }
        values.push((w[0].clone(), line));
        at += 1;
    }
    Ok((values, at))
}

/// The rows of initial positions after the table's header lines from
/// row `at` on: max(1, `turbines`) of them, and the first one's 1-based
/// line.
fn read_platforms(
    rows: &[&str],
    mut at: usize,
    turbines: i64,
) -> Result<(Vec<[f64; 8]>, usize), DriverError> {
    // The Initial Positions section line and its table header lines.
    while rows.get(at).is_some_and(|r| {
        let first = words(r).into_iter().next();
        !is_end(r) && first.is_none_or(|w| w.parse::<f64>().is_err())
    }) {
        at += 1;
    }
    let first_platform = at + 1;
    let mut platforms = Vec::new();
    for _ in 0..turbines.max(1) {
        let line = at + 1;
        let row = rows.get(at).ok_or_else(|| DriverError {
            line,
            message: "the file ends where a row of initial positions (ref_X ref_Y surge sway \
                      heave roll pitch yaw) is expected"
                .into(),
        })?;
        platforms.push(platform_row(row, line)?);
        at += 1;
    }
    Ok((platforms, first_platform))
}

/// The driver's last line, `END of driver input file`.
fn is_end(row: &str) -> bool {
    row.trim_start().to_ascii_uppercase().starts_with("END")
}

/// One row of initial positions: 8 finite numbers.
fn platform_row(row: &str, line: usize) -> Result<[f64; 8], DriverError> {
    let w = words(row);
    let numbers: Vec<f64> = w
        .iter()
        .take(8)
        .map_while(|v| v.parse::<f64>().ok().filter(|x| x.is_finite()))
        .collect();
    numbers.try_into().map_err(|_| DriverError {
        line,
        message: format!(
            "expected 8 numbers (ref_X ref_Y surge sway heave roll pitch yaw), found {:?}",
            row.trim()
        ),
    })
}

/// The words of a line as Fortran's list-directed read splits them: by
/// blanks and commas, a quoted string one word without its quotes.
fn words(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut chars = line.chars().peekable();
    while let Some(&c) = chars.peek() {
        if c.is_whitespace() || c == ',' {
            chars.next();
            continue;
        }
        let mut word = String::new();
        if c == '"' || c == '\'' {
            chars.next();
            for d in chars.by_ref() {
                if d == c {
                    break;
                }
                word.push(d);
            }
        } else {
            while let Some(&d) = chars.peek() {
                if d.is_whitespace() || d == ',' {
                    break;
                }
                word.push(d);
                chars.next();
            }
        }
        out.push(word);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const HORIZONTAL: &str = "MoorDyn driver input file \nanother comment line\n\
---------------------- ENVIRONMENTAL CONDITIONS ---------------- \n\
9.80665            Gravity          - Gravity (m/s^2) \n\
1025.0             rhoW             - Water density (kg/m^3) \n\
75.0              WtrDpth          - Water depth (m) \n\
---------------------- MOORDYN --------------------------------- \n\
\"horizontal.dat\"      MDInputFile      - Primary MoorDyn input file name (quoted string) \n\
\"driver\"            OutRootName      - The name which prefixes all generated files \n\
60                  TMax             - Number of time steps in the simulations (-) \n\
0.001                 dtC              - TimeInterval for the simulation (sec) \n\
0                   InputsMode       - MoorDyn coupled object inputs (switch) \n\
\"\"   InputsFile       - Filename for the MoorDyn inputs file (quoted string) \n\
0                   NumTurbines      - Number of wind turbines (-) \n\
---------------------- Initial Positions ----------------------- \n\
ref_X    ref_Y    surge_init   sway_init  heave_init  roll_init  pitch_init   yaw_init \n\
(m)      (m)        (m)          (m)        (m)       (rad)       (rad)        (rad) \n\
0         0          0            0          0          0           0            0 \n\
END of driver input file \n";

    #[test]
    fn openfasts_horizontal_driver_file_is_read_value_by_value() {
        assert!(looks_like_driver(HORIZONTAL));
        let d = parse_driver(HORIZONTAL).unwrap();
        assert_eq!(d.gravity, 9.80665);
        assert_eq!(d.water_density, 1025.0);
        assert_eq!(d.water_depth, 75.0);
        assert_eq!(d.deck, "horizontal.dat");
        assert_eq!(d.out_root, "driver");
        assert_eq!((d.t_max, d.dt_c), (60.0, 0.001));
        assert_eq!((d.inputs_mode, d.inputs_file.as_str()), (0, ""));
        assert_eq!(d.turbines, 0);
        assert_eq!(d.platforms, vec![[0.0; 8]]);
        assert_eq!(d.lines[5], 10);
        assert_eq!(d.lines[10], 18);
    }

    #[test]
    fn an_older_drivers_echo_flag_is_passed_over() {
        let echo = HORIZONTAL.replacen(
            "another comment line\n",
            "another comment line\nFALSE   Echo   - Echo the input file data (flag)\n",
            1,
        );
        let d = parse_driver(&echo).unwrap();
        assert_eq!(d.gravity, 9.80665);
        assert_eq!(d.platforms, vec![[0.0; 8]]);
        assert_eq!(d.lines[10], 19);
    }

    #[test]
    fn a_driver_line_out_of_its_order_is_refused_naming_it() {
        let swapped = HORIZONTAL.replacen("60                  TMax", "60                  dtC", 1);
        let e = parse_driver(&swapped).unwrap_err();
        assert_eq!(e.line, 10);
        assert!(e.message.contains("TMax"), "{e}");
        let mode = HORIZONTAL.replacen("0                   InputsMode", "2 InputsMode", 1);
        let e = parse_driver(&mode).unwrap_err();
        assert_eq!(e.line, 12);
        assert!(e.message.contains("InputsMode 2"), "{e}");
        let short = HORIZONTAL.replacen(
            "0         0          0            0          0          0           0            0",
            "0 0 0",
            1,
        );
        let e = parse_driver(&short).unwrap_err();
        assert_eq!(e.line, 18);
        let dt = HORIZONTAL.replacen("0.001                 dtC", "0 dtC", 1);
        assert!(parse_driver(&dt).unwrap_err().message.contains("positive"));
    }
}
