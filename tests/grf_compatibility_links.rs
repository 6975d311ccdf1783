//! Every citation of a `docs/grf-compatibility.md` section by its anchor in the repository (code
//! comments, docstrings, `.tl` files, docs) names an anchor the page defines (`<a id="…">`), so that a
//! renamed or removed section cannot leave a dead reference behind.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

const PAGE: &str = "docs/grf-compatibility.md";
/// The kinds of file that cite the page.
const EXTENSIONS: [&str; 8] = ["rs", "py", "pyi", "md", "tl", "rhai", "html", "toml"];
/// Folders never searched: build output, VCS data, caches.
const SKIP: [&str; 5] = ["target", ".git", "node_modules", "__pycache__", ".ruff_cache"];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("tests/ sits in the workspace root").to_path_buf()
}

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).expect("readable folder").flatten() {
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        if path.is_dir() {
            if !SKIP.contains(&name.as_str()) && !name.starts_with('.') {
                files(&path, out);
            }
        } else if path.extension().is_some_and(|e| EXTENSIONS.contains(&e.to_string_lossy().as_ref())) {
            out.push(path);
        }
    }
}

/// The anchors cited right after `grf-compatibility.md`: `#a` and any `, #b` that follow.
fn cited(text: &str) -> Vec<String> {
    let mut anchors = Vec::new();
    for (at, _) in text.match_indices("grf-compatibility.md#") {
        let mut rest = &text[at + "grf-compatibility.md".len()..];
        while let Some(after) = rest.strip_prefix('#') {
            let end = after
                .find(|c: char| !(c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'))
                .unwrap_or(after.len());
            if end == 0 {
                // Not a citation: the text only names the page's address form (as this file does).
                break;
            }
            anchors.push(after[..end].to_string());
            rest = &after[end..];
            rest = rest.strip_prefix(", ").unwrap_or(rest);
        }
    }
    anchors
}

#[test]
fn every_cited_anchor_exists() {
    let root = root();
    let page = fs::read_to_string(root.join(PAGE)).expect("the compatibility page exists");
    let defined: BTreeSet<&str> = page.split("<a id=\"").skip(1).filter_map(|s| s.split('"').next()).collect();
    let mut paths = Vec::new();
    files(&root, &mut paths);
    let mut dead = Vec::new();
    let mut count = 0;
    for path in paths {
        let Ok(text) = fs::read_to_string(&path) else { continue };
        for anchor in cited(&text) {
            count += 1;
            if !defined.contains(anchor.as_str()) {
                dead.push(format!("{}: #{anchor}", path.strip_prefix(&root).unwrap_or(&path).display()));
            }
        }
    }
    assert!(count > 50, "only {count} citations found: is the search looking in the right place?");
    assert!(dead.is_empty(), "citations of anchors {PAGE} does not define:\n{}", dead.join("\n"));
}

#[test]
fn citations_are_read_with_their_continuations() {
    assert_eq!(cited("(docs/grf-compatibility.md#laws, #pitch-geometry)."), ["laws", "pitch-geometry"]);
    assert_eq!(cited("[x](../docs/grf-compatibility.md#roles)"), ["roles"]);
}
