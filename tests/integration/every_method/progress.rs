//! Progress reports of long runs and the one-line summaries of every method's statistics.

use std::time::Duration;

use dirac::State;
use dirac::prelude::*;

use super::Fineness;
use crate::zoo::ForcedSpring;

/// With a zero interval the report comes after every step but the last and once at the end:
/// times rising to the end, the counters those of the run, the fraction from 0 to 1. With a long
/// interval, only the final report.
#[test]
fn every_method_reports_its_progress_and_summarises_its_work() {
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let mut start = State::<ForcedSpring>::zeros();
    start.set_q(ForcedSpring::X, 0.5);
    each_integrator!(&mut spring, Fineness::new(1e-8, 1e-10, 1e-2), |method, integrator| {
        let mut reports = Vec::new();
        let solution = integrator
            .solve_with_progress(0.0, &start, 5.0, &Sampling::Steps, Duration::ZERO, |p| {
                reports.push((p.t, p.fraction(), format!("{p}"), p.bar(10)));
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let steps = solution.len() - 1;
        assert_eq!(reports.len(), steps, "{method:?}: one report per step");
        assert!(reports.windows(2).all(|w| w[0].0 < w[1].0 && w[0].1 <= w[1].1), "{method:?}");
        let (t, fraction, line, bar) = reports.last().expect("a final report");
        assert_eq!((*t, *fraction), (5.0, 1.0), "{method:?}");
        assert_eq!(bar, "[##########]");
        let summary = format!("{}", solution.stats);
        assert!(summary.starts_with(&format!("{steps} steps")), "{method:?}: {summary}");
        assert!(
            line.starts_with("t = 5.000000 of 5 (100%), ") && line.contains(&summary),
            "{method:?}: {line}"
        );

        let mut count = 0;
        integrator
            .solve_with_progress(0.0, &start, 5.0, &Sampling::Steps, Duration::from_secs(3600), |_| {
                count += 1
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        assert_eq!(count, 1, "{method:?}: only the final report");
    });
}
