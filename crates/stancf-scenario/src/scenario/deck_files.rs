//! Files a MoorDyn deck names by path (`SeafloorFile`), found as MoorDyn
//! finds them and also where a suite keeps them (docs/interface.md,
//! "MoorDyn decks"): MoorDyn opens the path as written, relative to the
//! working directory of its process (its own test decks name their files
//! relative to its tests folder, `Mooring/3D_seafloor/...`); stancf tries
//! that first, then the deck's folder and each folder above it, so a deck
//! runs from wherever its suite keeps it. `check` says which file it
//! found where.

use std::path::{Path, PathBuf};

/// A file a deck names, and where it was found.
#[derive(Clone, Debug, PartialEq)]
pub struct FoundFile {
    pub path: PathBuf,
    /// "relative to the working directory, as MoorDyn opens it", "beside
    /// the deck", "relative to /suite/tests" or "as given" (absolute).
    pub place: String,
}

/// The file `named` (as the deck at `deck_path` writes it): the first of
/// the working directory's, the deck folder's and its parents' that is a
/// file. Else what was tried.
pub fn locate(named: &str, deck_path: &Path) -> Result<FoundFile, String> {
    let as_named = Path::new(named);
    if as_named.is_absolute() {
        return if as_named.is_file() {
            Ok(FoundFile {
                path: as_named.to_path_buf(),
                place: "as given".into(),
            })
        } else {
            Err(format!("{named} is not a file"))
        };
    }
    let mut places: Vec<(PathBuf, String)> = Vec::new();
    if let Ok(cwd) = std::env::current_dir() {
        places.push((
            cwd,
            "relative to the working directory, as MoorDyn opens it".into(),
        ));
    }
    let deck_dir = match deck_path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let deck_dir = std::fs::canonicalize(deck_dir).unwrap_or_else(|_| deck_dir.to_path_buf());
    for (k, dir) in deck_dir.ancestors().enumerate() {
        let place = if k == 0 {
            "beside the deck".to_string()
        } else {
            format!("relative to {}, a folder above the deck's", dir.display())
        };
        places.push((dir.to_path_buf(), place));
    }
    let mut tried: Vec<PathBuf> = Vec::new();
    for (dir, place) in places {
        let path = dir.join(as_named);
        if tried.contains(&path) {
            continue;
        }
        if path.is_file() {
            return Ok(FoundFile { path, place });
        }
        tried.push(path);
    }
    Err(format!(
        "no file {named} relative to the working directory (where MoorDyn looks), the deck's \
         folder {} or any folder above it",
        deck_dir.display()
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_named_from_a_suites_folder_is_found_above_the_deck() {
        let root = std::env::temp_dir().join(format!("stancf-deck-files-{}", std::process::id()));
        let decks = root.join("tests").join("Mooring");
        let beds = decks.join("3D_seafloor");
        std::fs::create_dir_all(&beds).unwrap();
        std::fs::write(beds.join("bed.txt"), "1 1\n0\n0\n0 0 -1\n").unwrap();
        std::fs::write(decks.join("beside.txt"), "").unwrap();
        let deck = decks.join("deck.txt");
        let found = locate("Mooring/3D_seafloor/bed.txt", &deck).unwrap();
        let tests_dir = std::fs::canonicalize(root.join("tests")).unwrap();
        assert_eq!(found.path, tests_dir.join("Mooring/3D_seafloor/bed.txt"));
        assert!(
            found.place.contains(&tests_dir.display().to_string()),
            "{}",
            found.place
        );
        assert_eq!(
            locate("beside.txt", &deck).unwrap().place,
            "beside the deck"
        );
        let e = locate("Mooring/none.txt", &deck).unwrap_err();
        assert!(e.contains("no file Mooring/none.txt"), "{e}");
        std::fs::remove_dir_all(&root).unwrap();
    }
}
