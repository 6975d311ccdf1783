//! Runnable examples live in `rust/`; this library is empty.
