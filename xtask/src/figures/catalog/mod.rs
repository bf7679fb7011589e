//! Every figure a document may quote: its name (the block's), the command that makes
//! it (shown by `--list`, and in the block itself where it is an output), and how its
//! text is made from that command's output. By topic: [`plan`] (what `zerocal plan`
//! and `zerocal program` promise, and the worked examples of `zerocal session`),
//! [`sim`] (the Monte-Carlo tables the tests and `zerocal error-table` print),
//! [`firmware`] (the firmware's saved measurements against its budgets), [`headline`]
//! (the README's one-line summaries of those), [`web`] (the web application's fleet
//! page at a plant's scale).

mod firmware;
mod headline;
mod plan;
mod sim;
mod web;

use anyhow::{anyhow, Result};

use super::sources::Sources;

/// A figure: a block's name, its command, and how its text is made.
pub struct Figure {
    /// The name blocks use (`<!-- figures:NAME -->`).
    pub name: &'static str,
    /// The command that makes it.
    pub command: &'static str,
    /// Its text.
    pub make: fn(&mut Sources) -> Result<String>,
}

/// A command's output as the documents show it: a `text` fence whose first line is the
/// command.
pub fn fenced(command: &str, output: &str) -> String {
    let mut text = format!("```text\n$ {command}\n{}", output.trim_end());
    text.push_str("\n```\n");
    text
}

/// What the test prints, fenced under its command.
pub fn test_fenced(s: &mut Sources, package: &str, test: &str, name: &str) -> Result<String> {
    let out = s.test(package, test, name)?;
    Ok(fenced(
        &format!("cargo test -p {package} --test {test} -- --exact {name} --nocapture"),
        &out,
    ))
}

/// The first line of `text` that starts with `prefix`.
pub fn line_starting<'t>(text: &'t str, prefix: &str) -> Result<&'t str> {
    text.lines()
        .find(|l| l.starts_with(prefix))
        .ok_or_else(|| anyhow!("no line starting '{prefix}' in:\n{text}"))
}

/// The word after `before` in `line` (up to the next space, comma, ';' or ')').
pub fn word_after<'t>(line: &'t str, before: &str) -> Result<&'t str> {
    let at = line
        .find(before)
        .ok_or_else(|| anyhow!("no '{before}' in '{line}'"))?;
    let rest = &line[at + before.len()..];
    Ok(rest
        .split(|c: char| c.is_whitespace() || matches!(c, ',' | ';' | ')'))
        .next()
        .unwrap_or_default())
}

/// The whitespace-separated fields of the table rows of `text` whose first field is one
/// of `rows` (a Monte-Carlo table: a robot a row).
pub fn rows<'t>(text: &'t str, first: &[&str]) -> Vec<Vec<&'t str>> {
    text.lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|f| f.first().is_some_and(|w| first.contains(w)))
        .collect()
}

/// A number field.
pub fn number(field: &str) -> Result<f64> {
    field
        .trim_end_matches('%')
        .parse()
        .map_err(|_| anyhow!("'{field}' is not a number"))
}

/// `lo-hi` of values printed with `decimals`, or the one value when they are equal.
pub fn range(values: &[f64], decimals: usize) -> Result<String> {
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !lo.is_finite() || !hi.is_finite() {
        return Err(anyhow!("no values"));
    }
    let (lo, hi) = (format!("{lo:.decimals$}"), format!("{hi:.decimals$}"));
    Ok(if lo == hi { lo } else { format!("{lo}-{hi}") })
}

/// Every figure.
pub static CATALOG: &[Figure] = &[
    plan::PLAN_WINDOW,
    plan::PLAN_MARGIN,
    plan::PLAN_KR6_SUMMARY,
    plan::SIMULATE_U_KR6,
    plan::PLAN_KR16,
    plan::PLAN_PER_PROFILE,
    plan::PLAN_TARGET_REFUSED,
    plan::ROBOT_TIME_KR6,
    plan::ROBOT_TIME_KR16,
    plan::ROBOT_TIME_OVER,
    plan::CHECK_TIME_PER_PROFILE,
    plan::SESSION_KR6_EXAMPLE,
    plan::SESSION_IRB140_EXAMPLE,
    plan::SESSION_KR6_MAMES,
    plan::ROBOTS_EXAMPLE,
    sim::ERROR_TABLE_FOUR,
    sim::ERROR_TABLE_REAL_ARM,
    sim::REAL_WORLD,
    sim::REAL_ARM_BUDGET,
    sim::REAL_ARM_FANUC,
    sim::REAL_ARM_EFFECTS,
    sim::BRACKETS_ACCEPTANCE,
    sim::MOUNTING_EFFECTS,
    sim::TABLE4,
    sim::SINGLE_STEP,
    sim::TILT_NOT_TARE,
    sim::IDENTIFICATION_CHECKS,
    sim::PLANNED_POSES,
    sim::SESSION_HONESTY,
    sim::EVERY_PROFILE,
    sim::RESTORE_CHECK,
    sim::INDEPENDENT_LOGS,
    sim::PENDANT_SIM_SESSION,
    firmware::FIRMWARE_TABLE,
    firmware::ON_TARGET,
    firmware::FIRMWARE_SIZE_TABLE,
    headline::REAL_ARM_HEADLINE,
    headline::TCP_HEADLINE,
    headline::PENDANT_EFFECTS_HEADLINE,
    headline::RESTORE_HEADLINE,
    headline::FIRMWARE_HEADLINE,
    headline::TARGET_FIT_HEADLINE,
    web::FLEET_PAGE_LOAD,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_fields_read() {
        let mut names: Vec<&str> = CATALOG.iter().map(|f| f.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), CATALOG.len());
        assert_eq!(range(&[97.5, 100.0, 98.0], 1).unwrap(), "97.5-100.0");
        assert_eq!(range(&[0.0, 0.0], 0).unwrap(), "0");
        let t = "robot  a  b\nkr6  1.5 50.0 %\nabb  2.0 40 %\n";
        let r = rows(t, &["kr6", "abb"]);
        assert_eq!(r.len(), 2);
        assert_eq!(number(r[1][1]).unwrap(), 2.0);
        assert_eq!(
            word_after("readings within +/-6.00 deg", "within +/-").unwrap(),
            "6.00"
        );
        assert!(fenced("zerocal x", "out\n").starts_with("```text\n$ zerocal x\nout\n```"));
    }
}
