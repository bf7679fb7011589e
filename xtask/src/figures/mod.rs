//! `cargo xtask figures [--check] [--only NAME…] [--list]`: one source for every figure.
//!
//! Every number the README and docs/ quote from a simulation, a budget, an example's
//! output or the firmware's size sits in a marked block ([`blocks`]) that names the
//! figure which writes it; each figure is made by one command ([`catalog`]: a `zerocal`
//! run, a test that prints what it measured, the firmware's saved measurements), run
//! once however many blocks quote it ([`sources`]). Without `--check` the blocks are
//! written; with it nothing is, and every block whose text is not what its command
//! makes now is named with the difference: a figure edited by hand, or one its code
//! has moved, fails CI. A block whose name no figure has, and a figure no document
//! uses, are errors too.
//!
//! Everything is seeded (the simulations by their `--seed` and the tests by theirs),
//! so the same tree gives the same text.

mod blocks;
mod catalog;
mod sources;

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{anyhow, bail, Context, Result};

use blocks::Block;
use catalog::{Figure, CATALOG};
use sources::Sources;

/// What `cargo xtask figures` was asked.
pub struct Options {
    /// Fail on a stale block instead of writing it.
    pub check: bool,
    /// Only these figures (empty: all).
    pub only: Vec<String>,
    /// List the figures and where they are used; run nothing.
    pub list: bool,
}

/// A document with its blocks.
struct Document {
    path: PathBuf,
    text: String,
    blocks: Vec<Block>,
}

/// README.md and every Markdown file under docs/, in a fixed order.
fn documents(root: &Path) -> Result<Vec<Document>> {
    let mut paths = vec![root.join("README.md")];
    let mut dirs = vec![root.join("docs")];
    while let Some(dir) = dirs.pop() {
        for entry in fs::read_dir(&dir).with_context(|| format!("reading {}", dir.display()))? {
            let path = entry?.path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "md") {
                paths.push(path);
            }
        }
    }
    paths.sort();
    paths
        .into_iter()
        .map(|path| {
            let text =
                fs::read_to_string(&path).with_context(|| format!("reading {}", path.display()))?;
            let blocks = blocks::parse(&text).with_context(|| format!("{}", path.display()))?;
            Ok(Document { path, text, blocks })
        })
        .collect()
}

fn figure(name: &str) -> Option<&'static Figure> {
    CATALOG.iter().find(|f| f.name == name)
}

/// Where each figure is used: its documents and lines.
fn uses(root: &Path, docs: &[Document]) -> BTreeMap<String, Vec<String>> {
    let mut uses: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for doc in docs {
        let shown = doc.path.strip_prefix(root).unwrap_or(&doc.path).display();
        for b in &doc.blocks {
            uses.entry(b.name.clone())
                .or_default()
                .push(format!("{shown}:{}", b.line));
        }
    }
    uses
}

/// The first line where `old` and `new` differ, for a stale block's message.
fn first_difference(old: &str, new: &str) -> String {
    let (a, b): (Vec<&str>, Vec<&str>) = (old.lines().collect(), new.lines().collect());
    for k in 0..a.len().max(b.len()) {
        let (x, y) = (a.get(k).copied(), b.get(k).copied());
        if x != y {
            return format!(
                "    its line {}: the document has  {}\n    {:>w$}  the command makes {}",
                k + 1,
                x.map_or("(nothing)".to_owned(), |l| format!("'{l}'")),
                "",
                y.map_or("(nothing)".to_owned(), |l| format!("'{l}'")),
                w = format!("its line {}:", k + 1).len()
            );
        }
    }
    "    (line ends differ)".to_owned()
}

/// Runs `cargo xtask figures`.
///
/// # Errors
/// A broken or unknown block, an unused figure, a command that fails, a file that
/// cannot be written; with `--check`, a stale block.
pub fn run(root: &Path, options: &Options) -> Result<()> {
    let started = Instant::now();
    let docs = documents(root)?;
    let used = uses(root, &docs);
    if options.list {
        for f in CATALOG {
            let at = used
                .get(f.name)
                .map_or("UNUSED".to_owned(), |u| u.join(", "));
            println!("{}\n    {}\n    used in {at}", f.name, f.command);
        }
        return Ok(());
    }
    for (name, at) in &used {
        if figure(name).is_none() {
            bail!(
                "{}: 'figures:{name}' is no figure (`cargo xtask figures --list`)",
                at.join(", ")
            );
        }
    }
    for name in &options.only {
        if figure(name).is_none() {
            bail!("--only {name}: no such figure (`cargo xtask figures --list`)");
        }
    }
    if options.only.is_empty() {
        let unused: Vec<&str> = CATALOG
            .iter()
            .map(|f| f.name)
            .filter(|n| !used.contains_key(*n))
            .collect();
        if !unused.is_empty() {
            bail!(
                "figures no document uses (a block was removed, or the figure is dead): {}",
                unused.join(", ")
            );
        }
    }
    let wanted: BTreeSet<&str> = used
        .keys()
        .map(String::as_str)
        .filter(|n| options.only.is_empty() || options.only.iter().any(|o| o == n))
        .collect();
    let mut sources = Sources::new(root);
    let mut made: BTreeMap<&str, String> = BTreeMap::new();
    for name in &wanted {
        let f = figure(name).ok_or_else(|| anyhow!("no figure {name}"))?;
        let text =
            (f.make)(&mut sources).with_context(|| format!("figure '{name}' ({})", f.command))?;
        made.insert(name, text);
    }
    let mut stale = Vec::new();
    let mut written = 0;
    for doc in &docs {
        let shown = doc.path.strip_prefix(root).unwrap_or(&doc.path).display();
        let new = blocks::replace(&doc.text, &doc.blocks, |b| {
            let old = &doc.text[b.text.clone()];
            let Some(text) = made.get(b.name.as_str()) else {
                return Ok(old.to_owned());
            };
            let mut text = text.clone();
            if b.inline {
                text = text.trim_end_matches('\n').to_owned();
            } else if !text.is_empty() && !text.ends_with('\n') {
                text.push('\n');
            }
            if text != old {
                stale.push(format!(
                    "{shown}:{} 'figures:{}' is not what `{}` makes now:\n{}",
                    b.line,
                    b.name,
                    figure(&b.name).map_or("", |f| f.command),
                    first_difference(old, &text)
                ));
            }
            Ok(text)
        })
        .with_context(|| format!("{shown}"))?;
        if !options.check && new != doc.text {
            fs::write(&doc.path, &new).with_context(|| format!("writing {shown}"))?;
            written += 1;
        }
    }
    let took = started.elapsed().as_secs_f64();
    if options.check {
        if !stale.is_empty() {
            bail!(
                "{} stale block(s): write them with `cargo xtask figures`:\n{}",
                stale.len(),
                stale.join("\n")
            );
        }
        println!(
            "figures: {} figure(s) in {} block(s), all as their commands make them ({took:.0} s)",
            made.len(),
            used.values().map(Vec::len).sum::<usize>()
        );
    } else {
        println!(
            "figures: {} figure(s) made, {} block(s) rewritten in {written} file(s) ({took:.0} s)",
            made.len(),
            stale.len()
        );
    }
    Ok(())
}
