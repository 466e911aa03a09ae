//! MoorDyn's viscoelastic LINE TYPES columns (docs/method.md §2.11):
//! `EA|EA_D` (a constant dynamic stiffness) or `EA|alphaMBL|vbeta` (the
//! mean-load dynamic stiffness alpha + beta T1), with `BA|BA_D` (the
//! dashpots beside the static and the dynamic spring), read as MoorDyn's
//! `readLineProps` reads them; the law itself is the library's
//! [`stancf::element::Viscoelastic`].

use super::layout::Row;
use super::DeckError;
use stancf::element::DynamicStiffness;

/// A line type's viscoelastic columns.
pub(crate) struct ViscoColumns {
    /// The static EA (N).
    pub ea: f64,
    pub dynamic: DynamicStiffness,
    /// BA (N s), or minus a damping ratio as for any line.
    pub ba: f64,
    /// BA_D (N s).
    pub ba_dynamic: f64,
}

/// BA_D, which must not be negative: MoorDyn refuses a ratio there.
pub(crate) fn dynamic_damping(ba_dynamic: f64) -> Result<f64, String> {
    if ba_dynamic < 0.0 {
        return Err(format!(
            "BA_D is {ba_dynamic}; the dynamic damping cannot be a ratio (MoorDyn refuses it too)"
        ));
    }
    Ok(ba_dynamic)
}

/// The viscoelastic forms of row `row` (line type `name`), None when EA
/// has one value (or is a Syrope form, refused elsewhere).
pub(crate) fn viscoelastic(row: &Row, name: &str) -> Result<Option<ViscoColumns>, DeckError> {
    let (ea_word, ba_word) = (row.words[3], row.words[4]);
    let ea: Vec<&str> = ea_word.split('|').collect();
    let ba: Vec<&str> = ba_word.split('|').collect();
    if ea_word.to_ascii_uppercase().starts_with("SYROPE:") {
        return Ok(None);
    }
    let err = |msg: String| DeckError::at(row.line, format!("line type \"{name}\": {msg}"));
    if ba.len() > ea.len() {
        return Err(err(format!(
            "BA is \"{ba_word}\", with more bar-separated values than EA \"{ea_word}\" (MoorDyn \
             refuses it: BA|BA_D goes with a viscoelastic EA|EA_D or EA|alphaMBL|vbeta)"
        )));
    }
    if ea.len() == 1 {
        return Ok(None);
    }
    if ea.len() > 3 || ba.len() > 2 {
        return Err(err(format!(
            "EA \"{ea_word}\" / BA \"{ba_word}\": EA takes at most 3 bar-separated values \
             (EA|EA_D or EA|alphaMBL|vbeta) and BA at most 2 (BA|BA_D)"
        )));
    }
    let value = |w: &str, what: &str| -> Result<f64, DeckError> {
        match w.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(err(format!(
                "{what} is \"{w}\", not a number{}",
                if what == "the static EA" {
                    " (stancf takes a constant static EA with a viscoelastic form, as MoorDyn's \
                     viscoelastic model uses)"
                } else {
                    ""
                }
            ))),
        }
    };
    let static_ea = value(ea[0], "the static EA")?;
    if static_ea <= 0.0 {
        return Err(err(format!(
            "the static EA is {static_ea}; it must be positive"
        )));
    }
    let dynamic = if ea.len() == 2 {
        DynamicStiffness::Constant(value(ea[1], "the dynamic stiffness EA_D")?)
    } else {
        DynamicStiffness::MeanLoad {
            alpha: value(ea[1], "alphaMBL")?,
            beta: value(ea[2], "vbeta")?,
        }
    };
    let ba_dynamic = match ba.get(1) {
        Some(w) => dynamic_damping(value(w, "BA_D")?).map_err(err)?,
        None => 0.0,
    };
    Ok(Some(ViscoColumns {
        ea: static_ea,
        dynamic,
        ba: value(ba[0], "BA")?,
        ba_dynamic,
    }))
}
