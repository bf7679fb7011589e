//! The marked blocks of a document: `<!-- figures:NAME -->` … `<!-- /figures:NAME -->`.
//!
//! A block is either on lines of its own (the start marker ends its line, the end marker
//! begins its line: the text between is whole lines, a table or a fenced output) or
//! inline (both markers on one line: a number or a phrase in a sentence or a table
//! cell). [`parse`] finds them, refusing a marker without its end, a name that is not
//! one, or a block inside another; [`replace`] writes new text into each.

use anyhow::{bail, Result};

/// The start of a start marker; the name and ` -->` follow.
const START: &str = "<!-- figures:";

/// The start of an end marker.
const END: &str = "<!-- /figures:";

/// The end of either marker.
const CLOSE: &str = " -->";

/// One block in a document.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Block {
    /// Its name: which figure writes it.
    pub name: String,
    /// Byte range of its text (between the markers; for a block on lines of its own,
    /// from the line after the start marker to the end of the line before the end
    /// marker, line ends included).
    pub text: std::ops::Range<usize>,
    /// Inline (both markers on one line).
    pub inline: bool,
    /// The line of its start marker (1-based).
    pub line: usize,
}

/// Whether a figure's name is one: lowercase letters, digits and `-`.
fn is_name(name: &str) -> bool {
    !name.is_empty()
        && name
            .bytes()
            .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'-')
}

/// The line (1-based) of byte `at`.
fn line_of(doc: &str, at: usize) -> usize {
    doc[..at].matches('\n').count() + 1
}

/// The first `marker` at or after `at` that is not quoted: one right after a backtick
/// is a marker shown in a code span (a page explaining the blocks), not a block.
fn find_marker(doc: &str, mut at: usize, marker: &str) -> Option<usize> {
    while let Some(i) = doc[at..].find(marker).map(|i| i + at) {
        if !doc[..i].ends_with('`') {
            return Some(i);
        }
        at = i + marker.len();
    }
    None
}

/// The blocks of `doc`, in order.
///
/// # Errors
/// A start marker whose end marker does not follow before the next start marker, an
/// end marker without its start, a name that is not one, or an inline block whose
/// text spans lines; each named by its line.
pub fn parse(doc: &str) -> Result<Vec<Block>> {
    let mut blocks = Vec::new();
    let mut at = 0;
    loop {
        let next_start = find_marker(doc, at, START);
        let next_end = find_marker(doc, at, END);
        let start = match (next_start, next_end) {
            (None, None) => break,
            (None, Some(e)) => bail!("line {}: an end marker without its start", line_of(doc, e)),
            (Some(s), Some(e)) if e < s => {
                bail!("line {}: an end marker without its start", line_of(doc, e))
            }
            (Some(s), _) => s,
        };
        let line = line_of(doc, start);
        let name_at = start + START.len();
        let Some(close) = doc[name_at..].find(CLOSE).map(|i| i + name_at) else {
            bail!("line {line}: a start marker not closed by ' -->'");
        };
        let name = &doc[name_at..close];
        if !is_name(name) {
            bail!("line {line}: '{name}' is not a figure's name (a-z, 0-9, '-')");
        }
        let end_marker = format!("{END}{name}{CLOSE}");
        let after = close + CLOSE.len();
        let Some(end) = doc[after..].find(&end_marker).map(|i| i + after) else {
            bail!("line {line}: no '{end_marker}' after 'figures:{name}'");
        };
        if let Some(inner) = find_marker(&doc[..end], after, START).map(|i| i - after) {
            bail!(
                "line {}: a block inside 'figures:{name}' (line {line})",
                line_of(doc, after + inner)
            );
        }
        let own_line = doc[after..].starts_with('\n');
        let inline = !own_line;
        let text = if inline {
            if doc[after..end].contains('\n') {
                bail!("line {line}: inline block 'figures:{name}' spans lines");
            }
            after..end
        } else {
            // The end marker begins its line.
            let line_start = doc[..end].rfind('\n').map_or(0, |i| i + 1);
            if !doc[line_start..end].trim().is_empty() {
                bail!(
                    "line {}: the end marker of 'figures:{name}' must begin its line",
                    line_of(doc, end)
                );
            }
            (after + 1)..line_start
        };
        blocks.push(Block {
            name: name.to_owned(),
            text,
            inline,
            line,
        });
        at = end + end_marker.len();
    }
    Ok(blocks)
}

/// `doc` with each block's text replaced by `text_of(block)` (a block on lines of its
/// own gets a final line end if its text lacks one).
///
/// # Errors
/// `text_of`'s, or a text of several lines for an inline block.
pub fn replace(
    doc: &str,
    blocks: &[Block],
    mut text_of: impl FnMut(&Block) -> Result<String>,
) -> Result<String> {
    let mut out = String::with_capacity(doc.len());
    let mut at = 0;
    for block in blocks {
        out.push_str(&doc[at..block.text.start]);
        let mut text = text_of(block)?;
        if block.inline {
            if text.contains('\n') {
                bail!(
                    "line {}: 'figures:{}' is inline, but its text has several lines",
                    block.line,
                    block.name
                );
            }
        } else if !text.is_empty() && !text.ends_with('\n') {
            text.push('\n');
        }
        out.push_str(&text);
        at = block.text.end;
    }
    out.push_str(&doc[at..]);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOC: &str = "# Title\n\nThe window is <!-- figures:window -->±6°<!-- /figures:window --> wide.\n\n<!-- figures:table -->\n| a | b |\n| 1 | 2 |\n<!-- /figures:table -->\nafter\n";

    #[test]
    fn finds_inline_and_line_blocks() {
        let blocks = parse(DOC).unwrap();
        assert_eq!(blocks.len(), 2);
        assert_eq!(blocks[0].name, "window");
        assert!(blocks[0].inline);
        assert_eq!(&DOC[blocks[0].text.clone()], "±6°");
        assert_eq!(blocks[0].line, 3);
        assert_eq!(blocks[1].name, "table");
        assert!(!blocks[1].inline);
        assert_eq!(&DOC[blocks[1].text.clone()], "| a | b |\n| 1 | 2 |\n");
    }

    #[test]
    fn replaces_each_block_and_nothing_else() {
        let blocks = parse(DOC).unwrap();
        let out = replace(DOC, &blocks, |b| {
            Ok(match b.name.as_str() {
                "window" => "±7°".into(),
                _ => "| x |".into(),
            })
        })
        .unwrap();
        assert_eq!(
            out,
            "# Title\n\nThe window is <!-- figures:window -->±7°<!-- /figures:window --> wide.\n\n<!-- figures:table -->\n| x |\n<!-- /figures:table -->\nafter\n"
        );
        // Replacing with what is there gives the document back.
        let same = replace(DOC, &blocks, |b| Ok(DOC[b.text.clone()].to_owned())).unwrap();
        assert_eq!(same, DOC);
        // An empty block on lines of its own stays empty.
        let empty = "<!-- figures:e -->\n<!-- /figures:e -->\n";
        let blocks = parse(empty).unwrap();
        assert_eq!(blocks[0].text.clone().count(), 0);
        let filled = replace(empty, &blocks, |_| Ok("x".into())).unwrap();
        assert_eq!(filled, "<!-- figures:e -->\nx\n<!-- /figures:e -->\n");
    }

    #[test]
    fn a_marker_in_a_code_span_is_text() {
        let doc = "Blocks are `<!-- figures:NAME -->` … `<!-- /figures:NAME -->`.\n";
        assert!(parse(doc).unwrap().is_empty());
    }

    #[test]
    fn broken_markers_are_named_by_line() {
        for (doc, says) in [
            (
                "a\n<!-- figures:x -->\nno end\n",
                "line 2: no '<!-- /figures:x -->'",
            ),
            (
                "<!-- /figures:x -->\n",
                "line 1: an end marker without its start",
            ),
            (
                "<!-- figures:X Y -->1<!-- /figures:X Y -->",
                "not a figure's name",
            ),
            (
                "<!-- figures:a -->\n<!-- figures:b -->1<!-- /figures:b -->\n<!-- /figures:a -->\n",
                "line 2: a block inside 'figures:a'",
            ),
            (
                "<!-- figures:a -->1\n2<!-- /figures:a -->",
                "inline block 'figures:a' spans lines",
            ),
            (
                "<!-- figures:a -->\n1 <!-- /figures:a -->\n",
                "must begin its line",
            ),
        ] {
            let e = parse(doc).unwrap_err().to_string();
            assert!(e.contains(says), "{doc:?}: {e}");
        }
        let blocks = parse("<!-- figures:a -->1<!-- /figures:a -->").unwrap();
        let e = replace("<!-- figures:a -->1<!-- /figures:a -->", &blocks, |_| {
            Ok("1\n2".into())
        })
        .unwrap_err();
        assert!(e.to_string().contains("several lines"), "{e}");
    }
}
