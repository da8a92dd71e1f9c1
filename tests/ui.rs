//! Compile-fail tests: each file under `tests/ui/<category>/` makes one mistake (or, in
//! `all_errors_at_once`, several) and its `.stderr` is the message a user sees. Files under
//! `tests/pass/` must compile. Bless changes with `TRYBUILD=overwrite cargo test --test ui`.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*/*.rs");
    t.pass("tests/pass/*.rs");
}
