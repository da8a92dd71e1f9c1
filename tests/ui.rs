//! Compile-fail tests: each file under `ui/<category>/` makes one mistake (or, in
//! `all_errors_at_once`, several) and its `.stderr` is the message a user sees. Files under
//! `pass/` must compile. Bless changes with `TRYBUILD=overwrite cargo test -p dirac-tests --test ui`.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("ui/*/*.rs");
    t.pass("pass/*.rs");
}
