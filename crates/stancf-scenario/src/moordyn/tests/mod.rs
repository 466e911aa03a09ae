//! Tests of the deck reader, by what they read: whole decks, options,
//! tables and output channels; the decks and helpers they share.

use super::*;

mod bodies;
mod channels;
mod decks;
mod failures;
mod options;
mod rods;
mod tables;

const OC4: &str = include_str!("../../../../../examples/oc4-deepcwind-moordyn.txt");

/// A small deck in the shape of MoorDyn's own test inputs
/// (`tests/Mooring/lines.txt`, `WD0200_Chain.txt`): `POINT PROPERTIES`,
/// `Vessel` points, comment text after the options, `fileIC` and
/// `disableOutTime`, no OUTPUTS, the `need this line` end marker.
const MOORDYN_TEST_STYLE: &str = "\
--------------------- MoorDyn Input File ------------------------------------
Single chain line for a finite difference check
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.25    390        1.6e9      -1.0        0          1.4    1.0    0.6     0.0
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m\u{2c6}3)   (m^2)  (-)
1     Fixed     700    0.0      -200.0  0      0       0      0
2     Vessel    0.0     0.0     0.0     0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         760       76      -
---------------------- OPTIONS -----------------------------------------
2                    writeLog             Write a log file
0.001                dtM                  time step
1.0e5                kBot                 bottom stiffness (Pa/m)
1.0e4                cBot                 bottom damping (Pa-s/m)
1025.0               WtrDnsty             water density (kg/m^3)
200                  WtrDpth              water depth (m)
1.0                  dtIC                 time interval for analyzing convergence during IC gen (s)
100.0                TmaxIC               max time for ic gen (s)
1.0e-4               threshIC             threshold for IC convergence (-)
WD0200_Chain.txt.ic  fileIC               Load a quasistatic solution before the IC solver (-)
0.5                  FrictionCoefficient  general bottom friction coefficient, as a start (-)
1       disableOutTime
------------------------- need this line --------------------------------------
";

/// A minimal deck; `{types}`, `{points}`, `{lines}`, `{options}` and
/// `{outputs}` are replaced by the tests.
const BASE: &str = "\
--- MoorDyn input ---
a test deck
--- LINE TYPES ---
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain 0.1 20 1e8 -0.8 0 1.2 1 0.4 0.5
--- POINTS ---
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -100 0 -50 0 0 0 0
2 Coupled 0 0 -5 0 0 0 0
--- LINES ---
ID LineType AttachA AttachB UnstrLen NumSegs Outputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 2 110 10 -
--- OPTIONS ---
0.001 dtM
--- OUTPUTS ---
FairTen1
--- END ---
";

fn with(find: &str, replace: &str) -> String {
    assert!(BASE.contains(find), "{find}");
    BASE.replacen(find, replace, 1)
}

fn error(text: &str) -> DeckError {
    parse(text).expect_err("the deck should be refused")
}

/// Whether the output channel `name` of the deck `text` (on a line of
/// its own) is refused naming its line, as MoorDyn refuses a channel of
/// an object the deck does not define (`Err`, the message), or read as
/// one MoorDyn does not know, which it warns of and skips (`Ok`, why).
fn channel_verdict(text: &str, name: &str) -> Result<String, String> {
    match parse(text) {
        Err(e) => {
            let n = text.lines().position(|l| l == name).unwrap() + 1;
            assert_eq!(e.line, Some(n), "{name}: {e}");
            assert!(
                e.message.starts_with(&format!("output channel \"{name}\"")),
                "{e}"
            );
            Err(e.message)
        }
        Ok(deck) => {
            let o = deck.outputs.iter().find(|o| o.name == name).expect(name);
            assert_eq!(o.channel, super::Channel::Unrecognized, "{name}");
            Ok(o.unrecognized.clone().expect("why"))
        }
    }
}

/// The 1-based number of the line of `text` that contains `needle`.
fn line_of(text: &str, needle: &str) -> usize {
    text.lines().position(|l| l.contains(needle)).expect(needle) + 1
}
