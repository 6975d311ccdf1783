//! Feeds arbitrary UTF-8 text to the scenario compiler: it must return (a scenario or
//! diagnostics), never panic, and every diagnostic's spans must lie inside its source on `char`
//! boundaries and render.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    let diags = match touchline_dsl::compile(text, "fuzz.tl") {
        Ok(compiled) => compiled.warnings,
        Err(diags) => diags,
    };
    for d in &diags.items {
        let source = d.source.inner();
        for (span, _) in &d.labels {
            assert!(span.start <= span.end && span.end <= source.len(), "{}: {span:?}", d.code);
            assert!(source.is_char_boundary(span.start) && source.is_char_boundary(span.end), "{}: {span:?}", d.code);
        }
    }
    let _ = diags.render_plain();
});
