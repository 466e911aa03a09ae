//! Pieces of the user's input echoed in messages: at most [`MAX_ECHO`]
//! characters each, so that no input, however long its lines or words
//! (a deck with CR-only line endings is one line of megabytes), floods a
//! terminal; a message is at most [`MAX_MESSAGE`] characters.

/// The longest piece of the user's input echoed in a message (in
/// characters); longer pieces are cut with an ellipsis.
pub const MAX_ECHO: usize = 200;

/// The longest message made of pieces of input (in characters).
pub const MAX_MESSAGE: usize = 2000;

/// `s` cut to at most `max` characters, with "…" (an ellipsis) where cut,
/// and its control characters but tab and newline (a NUL byte, an escape
/// that would drive the terminal) shown as "?".
pub fn clip(s: &str, max: usize) -> String {
    let shown = |t: &str| -> String {
        t.chars()
            .map(|c| {
                if c.is_control() && c != '\t' && c != '\n' {
                    '?'
                } else {
                    c
                }
            })
            .collect()
    };
    match s.char_indices().nth(max) {
        None => shown(s),
        Some((end, _)) => format!("{}…", shown(&s[..end])),
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

/// The lines of a text file, ended by `\n`, `\r\n` or a lone `\r` (the
/// line end of classic Mac OS files): as a text editor shows them, so
/// that the line numbers of messages are the editor's.
pub fn text_lines(text: &str) -> impl Iterator<Item = &str> {
    text.split_inclusive('\n').flat_map(|l| {
        let l = l.strip_suffix('\n').unwrap_or(l);
        let l = l.strip_suffix('\r').unwrap_or(l);
        l.split('\r')
    })
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
        assert_eq!(clip("wire\0\u{1b}[2J", 200), "wire??[2J");
    }
}
