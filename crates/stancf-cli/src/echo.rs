//! Pieces of the user's input echoed in messages: at most [`MAX_ECHO`]
//! characters each, so that no input, however long its lines or words
//! (a deck with CR-only line endings is one line of megabytes), floods a
//! terminal; a message is at most [`MAX_MESSAGE`] characters.

/// The longest piece of the user's input echoed in a message (in
/// characters); longer pieces are cut with an ellipsis.
pub const MAX_ECHO: usize = 200;

/// The longest message made of pieces of input (in characters).
pub const MAX_MESSAGE: usize = 2000;

/// `s` cut to at most `max` characters, with "…" (an ellipsis) where cut.
pub fn clip(s: &str, max: usize) -> String {
    match s.char_indices().nth(max) {
        None => s.to_string(),
        Some((end, _)) => format!("{}…", &s[..end]),
    }
}

/// `message` with every piece between double quotes cut to [`MAX_ECHO`]
/// characters, and the whole to [`MAX_MESSAGE`].
pub fn clip_quoted(message: &str) -> String {
    let mut out = String::with_capacity(message.len().min(MAX_MESSAGE + 8));
    for (k, piece) in message.split('"').enumerate() {
        if k > 0 {
            out.push('"');
        }
        // Odd pieces lie between quotes.
        if k % 2 == 1 {
            out.push_str(&clip(piece, MAX_ECHO));
        } else {
            out.push_str(piece);
        }
    }
    clip(&out, MAX_MESSAGE)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_quoted_piece_is_cut_and_the_rest_kept() {
        let long = "x".repeat(10_000);
        let m = clip_quoted(&format!("line 1: the header \"{long}\" names no section"));
        assert_eq!(
            m,
            format!(
                "line 1: the header \"{}…\" names no section",
                "x".repeat(200)
            )
        );
        assert_eq!(
            clip_quoted(&"y".repeat(5000)).chars().count(),
            MAX_MESSAGE + 1
        );
        assert_eq!(clip_quoted("a \"b\" c"), "a \"b\" c");
    }
}
