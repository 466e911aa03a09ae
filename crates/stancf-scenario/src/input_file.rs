//! Reading an input file (a scenario, a MoorDyn deck, a motion table, a
//! current profile): a regular file of at most [`MAX_INPUT_BYTES`], as
//! UTF-8 text. A folder, a device (`/dev/zero`), a pipe or a socket is
//! refused before anything is read, and no read goes past the bound, so an
//! input can never take the memory of the machine.

use std::io::Read;
use std::path::Path;

/// The largest input file (bytes): 64 MiB, about 1.5 million deck lines,
/// far above the largest real deck or motion table (a day of motion at
/// 10 Hz is 30 MB of CSV).
pub const MAX_INPUT_BYTES: u64 = 64 * 1024 * 1024;

/// The text of the input file at `path`, or what is wrong with it (a
/// message to follow the file's name: "not a regular file (a folder)").
pub fn read_text(path: &Path) -> Result<String, String> {
    // Looked at before it is opened: opening a pipe would wait for a
    // writer for ever.
    let meta = std::fs::metadata(path).map_err(|e| format!("cannot read the file: {e}"))?;
    if !meta.is_file() {
        return Err(format!(
            "not a regular file ({}); give the path of a file",
            kind_of(&meta)
        ));
    }
    let file = std::fs::File::open(path).map_err(|e| format!("cannot read the file: {e}"))?;
    let meta = file
        .metadata()
        .map_err(|e| format!("cannot read the file: {e}"))?;
    if !meta.is_file() {
        return Err(format!(
            "not a regular file ({}); give the path of a file",
            kind_of(&meta)
        ));
    }
    if meta.len() > MAX_INPUT_BYTES {
        return Err(too_large(meta.len()));
    }
    // A file that grows while it is read (or reports no size, as files
    // of /proc do) is read up to the bound and no further.
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    file.take(MAX_INPUT_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot read the file: {e}"))?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(too_large(bytes.len() as u64));
    }
    String::from_utf8(bytes).map_err(|e| {
        format!(
            "not UTF-8 text (byte {} is not valid UTF-8): an input file is text",
            e.utf8_error().valid_up_to()
        )
    })
}

/// The largest result file `stancf plot` reads back (bytes): the 4 GB a
/// run writes at most without `--allow-large`, with room.
pub const MAX_RESULT_FILE_BYTES: u64 = 8_000_000_000;

/// The text of a result file read back (`stancf plot`, a sweep's
/// summaries): a regular file, not a symbolic link, of at most
/// [`MAX_RESULT_FILE_BYTES`]; an error naming the file otherwise.
pub fn read_result_text(path: &Path) -> std::io::Result<String> {
    use std::io::{Error, ErrorKind};
    let refuse =
        |why: String| Error::new(ErrorKind::InvalidData, format!("{}: {why}", path.display()));
    let meta = std::fs::symlink_metadata(path)
        .map_err(|e| Error::new(e.kind(), format!("{}: {e}", path.display())))?;
    if meta.file_type().is_symlink() {
        return Err(refuse(
            "a symbolic link, not a result file stancf wrote".into(),
        ));
    }
    if !meta.is_file() {
        return Err(refuse(format!("not a regular file ({})", kind_of(&meta))));
    }
    if meta.len() > MAX_RESULT_FILE_BYTES {
        return Err(refuse(format!(
            "{} bytes, above the {MAX_RESULT_FILE_BYTES} a result file is read back with",
            meta.len()
        )));
    }
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_RESULT_FILE_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| Error::new(e.kind(), format!("{}: {e}", path.display())))?;
    String::from_utf8(bytes).map_err(|_| refuse("not UTF-8 text".into()))
}

fn too_large(bytes: u64) -> String {
    format!(
        "{} bytes, above the {} MiB an input file may have",
        bytes,
        MAX_INPUT_BYTES / (1024 * 1024)
    )
}

/// What a file that is not a regular file is, in words.
fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_fifo() {
            return "a pipe";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if meta.is_dir() {
        "a folder"
    } else {
        "not a file"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn devices_folders_and_oversized_files_are_refused_before_reading() {
        assert!(read_text(Path::new("/dev/zero"))
            .unwrap_err()
            .starts_with("not a regular file (a device)"));
        assert!(read_text(Path::new("/"))
            .unwrap_err()
            .starts_with("not a regular file (a folder)"));
        let dir = std::env::temp_dir().join(format!("stancf-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let big = dir.join("big.txt");
        let f = std::fs::File::create(&big).unwrap();
        // A sparse file: its length is all that is looked at.
        f.set_len(MAX_INPUT_BYTES + 1).unwrap();
        assert!(read_text(&big)
            .unwrap_err()
            .contains("above the 64 MiB an input file may have"));
        std::fs::write(&big, b"ok\xff").unwrap();
        assert!(read_text(&big)
            .unwrap_err()
            .starts_with("not UTF-8 text (byte 2"));
        std::fs::write(&big, "t,x,y,z\n").unwrap();
        assert_eq!(read_text(&big).unwrap(), "t,x,y,z\n");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
