//! The repository's structural rules, checked on its files so a change that breaks one
//! fails here with the file named:
//!
//! - no import circle between the top-level modules of a crate (a module imports
//!   another through `crate::name`; a circle means two ideas that cannot be read apart);
//! - no Rust source file over [`MAX_SOURCE_LINES`] lines;
//! - the repository map (docs/repository.md, linked from the README) names every
//!   top-level directory, and nothing the tree lacks;
//! - the desktop's product crates depend on one another only where one is made of the
//!   other (docs/repository.md): no crate holds two products through a dependency;
//! - no file refers to the notes beside the repository (the parent directory's shared
//!   folder): a user's clone has none of them; nor names the team's issues by number;
//! - the README is a landing page of at most [`MAX_README_LINES`] lines: what it is,
//!   the user's path, the two commands, how to flash, the headline figures and where the
//!   docs are; the details live in docs/.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// The longest a source file may be: one idea per file.
const MAX_SOURCE_LINES: usize = 900;

/// The longest the README may be: a landing page read on one screen or two.
const MAX_README_LINES: usize = 150;

#[test]
fn the_readme_is_a_landing_page() {
    let readme = fs::read_to_string(repo_root().join("README.md")).unwrap();
    let lines = readme.lines().count();
    assert!(
        lines <= MAX_README_LINES,
        "README.md has {lines} lines, over {MAX_README_LINES}: move the details to docs/"
    );
    // It leads with the user's path, before the developer's commands.
    let path = readme
        .find("## Calibrating a robot")
        .expect("the user's path");
    let commands = readme
        .find("## The two commands")
        .expect("the two commands");
    assert!(
        path < commands,
        "the developer's commands come before the user's path"
    );
}

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

/// Every file under `dir`, skipping build output, git data and fuzz artifacts.
fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            if !matches!(name.as_str(), "target" | ".git" | "artifacts" | "coverage") {
                files(&path, out);
            }
        } else {
            out.push(path);
        }
    }
}

/// The crates: every directory with a Cargo.toml and a src/.
fn crate_sources(root: &Path) -> Vec<PathBuf> {
    let mut all = Vec::new();
    files(root, &mut all);
    let mut out: Vec<PathBuf> = all
        .iter()
        .filter(|p| p.file_name().is_some_and(|n| n == "Cargo.toml"))
        .filter_map(|p| p.parent().map(|d| d.join("src")))
        .filter(|src| src.is_dir())
        .collect();
    out.sort();
    out
}

/// The top-level module a file of `src` belongs to (`lib`/`main` for the root files).
fn top_module(src: &Path, file: &Path) -> String {
    let rel = file.strip_prefix(src).unwrap();
    let first = rel
        .components()
        .next()
        .unwrap()
        .as_os_str()
        .to_string_lossy();
    first.trim_end_matches(".rs").to_string()
}

/// The `crate::name` paths a file's code uses: comments skipped, and its unit tests
/// (from `#[cfg(test)]` before `mod tests` on), which may drive any module.
fn crate_imports(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let lines: Vec<&str> = text.lines().collect();
    let end = lines
        .windows(2)
        .position(|w| w[0].trim() == "#[cfg(test)]" && w[1].trim_start().starts_with("mod tests"))
        .unwrap_or(lines.len());
    for line in &lines[..end] {
        let code = line.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(i) = rest.find("crate::") {
            let after = &rest[i + "crate::".len()..];
            let name: String = after
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            // `crate::{a, b}` groups: each name in the braces.
            if name.is_empty() && after.starts_with('{') {
                let group = after[1..].split('}').next().unwrap_or("");
                for part in group.split(',') {
                    let n: String = part
                        .trim()
                        .chars()
                        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                        .collect();
                    if !n.is_empty() {
                        out.insert(n);
                    }
                }
            } else if !name.is_empty() {
                out.insert(name);
            }
            rest = after;
        }
    }
    out
}

/// A circle in `graph`, if any, as the modules along it.
fn find_circle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(i) = path.iter().position(|n| n == node) {
            let mut circle = path[i..].to_vec();
            circle.push(node.to_string());
            return Some(circle);
        }
        if done.contains(node) {
            return None;
        }
        path.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            if let Some(c) = visit(next, graph, path, done) {
                return Some(c);
            }
        }
        path.pop();
        done.insert(node.to_string());
        None
    }
    let mut done = BTreeSet::new();
    for node in graph.keys() {
        if let Some(c) = visit(node, graph, &mut Vec::new(), &mut done) {
            return Some(c);
        }
    }
    None
}

#[test]
fn no_import_circle_between_the_modules_of_a_crate() {
    let root = repo_root();
    let mut circles = Vec::new();
    for src in crate_sources(&root) {
        let mut rs = Vec::new();
        files(&src, &mut rs);
        let modules: BTreeSet<String> = rs
            .iter()
            .filter(|p| p.extension().is_some_and(|e| e == "rs"))
            .map(|p| top_module(&src, p))
            .collect();
        let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for file in rs
            .iter()
            .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        {
            let from = top_module(&src, file);
            if from == "lib" || from == "main" {
                continue;
            }
            let text = fs::read_to_string(file).unwrap();
            for to in crate_imports(&text) {
                if to != from && modules.contains(&to) {
                    graph.entry(from.clone()).or_default().insert(to);
                }
            }
        }
        if let Some(circle) = find_circle(&graph) {
            circles.push(format!("{}: {}", src.display(), circle.join(" -> ")));
        }
    }
    assert!(
        circles.is_empty(),
        "import circles:\n{}",
        circles.join("\n")
    );
}

#[test]
fn the_circle_finder_finds_one() {
    // The check above can fail: a two-module circle is found and named.
    let mut graph = BTreeMap::new();
    graph.insert("log".to_string(), BTreeSet::from(["machine".to_string()]));
    graph.insert("machine".to_string(), BTreeSet::from(["log".to_string()]));
    graph.insert("link".to_string(), BTreeSet::from(["log".to_string()]));
    let circle = find_circle(&graph).unwrap();
    assert_eq!(circle.first(), circle.last());
    assert_eq!(circle.len(), 3);
    assert_eq!(
        crate_imports(
            "use crate::{log, machine::X};\n// crate::nothing\nlet a = crate::link::f();"
        ),
        BTreeSet::from(["log".to_string(), "machine".to_string(), "link".to_string()])
    );
}

#[test]
fn no_source_file_is_over_the_limit() {
    let root = repo_root();
    let mut all = Vec::new();
    files(&root, &mut all);
    let mut long: Vec<String> = all
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .filter_map(|p| {
            let n = fs::read_to_string(p).ok()?.lines().count();
            (n > MAX_SOURCE_LINES).then(|| format!("{} ({n} lines)", p.display()))
        })
        .collect();
    long.sort();
    assert!(
        long.is_empty(),
        "files over {MAX_SOURCE_LINES} lines:\n{}",
        long.join("\n")
    );
}

#[test]
fn nothing_refers_to_the_notes_beside_the_repository() {
    let root = repo_root();
    let mut all = Vec::new();
    files(&root, &mut all);
    let needle = ["..", "/shared"].concat();
    let mut found: Vec<String> = all
        .iter()
        .filter_map(|p| {
            let bytes = fs::read(p).ok()?;
            let text = String::from_utf8_lossy(&bytes);
            text.contains(needle.as_str())
                .then(|| p.display().to_string())
        })
        .collect();
    found.sort();
    assert!(
        found.is_empty(),
        "files naming {needle}:\n{}",
        found.join("\n")
    );
}

/// Whether `text` names one of the team's own issues by number (the word, a space and
/// the number): the tracker is not the user's; a reason is said in words. An upstream
/// project's issue cited as a source carries its `#` ("issue #377") and is not one.
fn names_an_issue_by_number(text: &str) -> bool {
    let needle = ["iss", "ue "].concat();
    let lower = text.to_lowercase();
    lower.match_indices(needle.as_str()).any(|(at, _)| {
        lower
            .as_bytes()
            .get(at + needle.len())
            .is_some_and(u8::is_ascii_digit)
    })
}

#[test]
fn no_file_names_the_team_s_issues_by_number() {
    assert!(names_an_issue_by_number(
        &["the target (Iss", "ue 34)"].concat()
    ));
    assert!(!names_an_issue_by_number("joint limits (issue #377)"));
    let root = repo_root();
    let mut all = Vec::new();
    files(&root, &mut all);
    let mut found: Vec<String> = all
        .iter()
        .filter(|p| {
            p.extension()
                .is_some_and(|e| ["rs", "md", "toml", "html", "sh"].iter().any(|x| e == *x))
        })
        .filter_map(|p| {
            let text = fs::read_to_string(p).ok()?;
            names_an_issue_by_number(&text).then(|| p.display().to_string())
        })
        .collect();
    found.sort();
    assert!(
        found.is_empty(),
        "files naming an issue by number:\n{}",
        found.join("\n")
    );
}

/// The paths docs/repository.md's "Repository" table names (the code spans of its first
/// column).
fn repository_map(page: &str) -> BTreeSet<String> {
    let Some(start) = page.find("# Repository") else {
        return BTreeSet::new();
    };
    let section = &page[start..];
    let end = section[3..].find("\n## ").map_or(section.len(), |i| i + 3);
    section[..end]
        .lines()
        .filter(|l| l.starts_with("| `"))
        .flat_map(|l| {
            let first = l.split('|').nth(1).unwrap_or("");
            first
                .split('`')
                .skip(1)
                .step_by(2)
                .map(|p| p.trim_end_matches('/').to_string())
                .collect::<Vec<_>>()
        })
        .collect()
}

#[test]
fn the_repository_map_matches_the_tree() {
    let root = repo_root();
    let page = fs::read_to_string(root.join("docs/repository.md")).unwrap();
    let named = repository_map(&page);
    // Every directory of the repository (build output, git and editor folders aside) and
    // every file the table names.
    let mut dirs: BTreeSet<String> = fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with('.') && n != "target")
        .collect();
    dirs.insert(".ci/run".to_string());
    let tops: BTreeSet<String> = named
        .iter()
        .map(|n| {
            if n.starts_with('.') {
                n.clone()
            } else {
                n.split('/').next().unwrap_or("").to_string()
            }
        })
        .collect();
    let missing: Vec<&String> = dirs.iter().filter(|d| !tops.contains(*d)).collect();
    assert!(
        missing.is_empty(),
        "docs/repository.md's map lacks {missing:?}"
    );
    let stale: Vec<&String> = named.iter().filter(|n| !root.join(n).exists()).collect();
    assert!(
        stale.is_empty(),
        "docs/repository.md's map names {stale:?}, which the tree lacks"
    );
}

/// The desktop's product crates and the only other products each may depend on
/// (docs/repository.md): the link client sends the plan `programs` makes; a
/// certificate is a session the analysis solves. Every one may use `zerocal-inputs`
/// and the method's crates below it.
const PRODUCTS: [(&str, &[&str]); 5] = [
    ("programs", &[]),
    ("link", &["zerocal-programs"]),
    ("analysis", &[]),
    ("records", &["zerocal-analysis"]),
    ("inputs", &[]),
];

/// The `zerocal-*` crates a manifest's dependencies name (not its dev-dependencies):
/// in `[dependencies]` and `[target.*.dependencies]`, as `name = ...`, as a renamed
/// `alias = { package = "zerocal-x" }` or as a `[dependencies.zerocal-x]` table.
fn zerocal_dependencies(manifest: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut in_deps = false;
    for line in manifest.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            let table = line.trim_matches(['[', ']']);
            in_deps = table == "dependencies" || table.ends_with(".dependencies");
            if let Some(name) = table.strip_prefix("dependencies.") {
                if name.starts_with("zerocal-") {
                    out.insert(name.to_string());
                }
            }
        } else if in_deps {
            let package = line
                .split("package")
                .nth(1)
                .and_then(|rest| rest.split('"').nth(1))
                .filter(|p| p.starts_with("zerocal-"));
            if let Some(p) = package {
                out.insert(p.to_string());
            } else if line.starts_with("zerocal-") {
                let name = line.split([' ', '=', '.']).next().unwrap_or("");
                out.insert(name.to_string());
            }
        }
    }
    out
}

#[test]
fn each_desktop_crate_is_one_product() {
    let root = repo_root();
    let products: BTreeSet<String> = PRODUCTS
        .iter()
        .map(|(dir, _)| format!("zerocal-{dir}"))
        .collect();
    let mut wrong = Vec::new();
    for (dir, allowed) in PRODUCTS {
        let manifest = fs::read_to_string(root.join(dir).join("Cargo.toml")).unwrap();
        for dep in zerocal_dependencies(&manifest) {
            let may = dep == "zerocal-inputs" || allowed.contains(&dep.as_str());
            if products.contains(&dep) && !may {
                wrong.push(format!("{dir}/Cargo.toml depends on {dep}"));
            }
        }
    }
    // `zerocal-inputs` is under every product: it depends on none of them.
    assert!(
        wrong.is_empty() && {
            let inputs = fs::read_to_string(root.join("inputs/Cargo.toml")).unwrap();
            zerocal_dependencies(&inputs).is_disjoint(&products)
        },
        "product crates that hold another product: {wrong:?}"
    );
}

#[test]
fn the_dependency_reader_reads_only_dependencies() {
    let manifest = "[package]\nname = \"zerocal-x\"\n[dependencies]\nzerocal-core = { path = \"../core\" }\nclap = \"4\"\nzerocal-sim.workspace = true\nsolver = { package = \"zerocal-analysis\", path = \"../analysis\" }\n[target.'cfg(unix)'.dependencies]\nzerocal-link = { path = \"../link\" }\n[dependencies.zerocal-records]\npath = \"../records\"\n[dev-dependencies]\nzerocal-web = { path = \"../web\" }\n";
    let names = [
        "zerocal-core",
        "zerocal-sim",
        "zerocal-analysis",
        "zerocal-link",
        "zerocal-records",
    ];
    assert_eq!(
        zerocal_dependencies(manifest),
        names.iter().map(|n| n.to_string()).collect::<BTreeSet<_>>()
    );
}
