//! Imports: presets and scenarios of other files, relative paths, cycles, unused imports.

use std::path::{Path, PathBuf};

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("lib")).unwrap();
    dir
}

#[test]
fn a_preset_from_an_imported_file_is_extended() {
    let dir = scratch("imports_ok");
    std::fs::write(
        dir.join("lib/presets.tl"),
        "/// Short drills without offsides.\npreset short_drill {\n  extends academy\n  game_duration 150\n  difficulty 0.3\n}\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("drill.tl"),
        "import \"lib/presets.tl\"\n\nscenario drill {\n  extends short_drill\n  team left { GK at (-1, 0) CF at (0.5, 0) }\n  team right { GK at (-1, 0) }\n  ball at (0.52, 0)\n}\n",
    )
    .unwrap();
    let c = touchline_dsl::compile_file(&dir.join("drill.tl")).unwrap_or_else(|d| panic!("{}", d.render_plain()));
    assert_eq!((c.scenario.game_duration, c.scenario.right_team_difficulty), (150, 0.3));
    assert!(
        c.scenario.end_episode_on_score && !c.scenario.offsides,
        "the prelude's academy preset, through the import"
    );
    assert!(c.warnings.items.is_empty());
    assert_eq!(c.files.len(), 2, "the watcher must see both files: {:?}", c.files);
}

#[test]
fn import_cycles_end_and_unused_imports_warn() {
    let dir = scratch("imports_cycle");
    std::fs::write(dir.join("a.tl"), "import \"b.tl\"\npreset pa { game_duration 100 }\n").unwrap();
    std::fs::write(dir.join("b.tl"), "import \"a.tl\"\npreset pb { extends pa }\n").unwrap();
    std::fs::write(
        dir.join("main.tl"),
        "import \"b.tl\"\nimport \"a.tl\"\nscenario m {\n  extends pb\n  team left { GK at (-1, 0) }\n  team right { GK at (-1, 0) }\n}\n",
    )
    .unwrap();
    let c = touchline_dsl::compile_file(&dir.join("main.tl")).unwrap_or_else(|d| panic!("{}", d.render_plain()));
    assert_eq!(c.scenario.game_duration, 100);
    let warnings: Vec<&str> = c.warnings.items.iter().map(|d| d.code.as_str()).collect();
    assert!(warnings.contains(&"tl::W102"), "main's import of a.tl is unused: {warnings:?}");
}
