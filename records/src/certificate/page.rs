//! The certificate as one HTML document for A4: its style (black on white, the page's
//! margins, the certificate's number and "page N of M" at every page's foot, as an
//! auditor expects each page identified) and its sections in order: what was calibrated,
//! how, the offsets, the decision and the signatures on page 1; the budget, the
//! residuals, the traceability and the notes on page 2.

use super::printed::Printed;
use super::sections::{self, Context};
use super::CertificateError;

/// The style. DejaVu Sans first: `cargo xtask setup` installs it with Chromium, so the
/// printed page is the same on every machine that renders it.
const STYLE: &str = r#"
@page {
  size: A4;
  margin: 12mm 14mm 14mm 14mm;
  @bottom-right { content: "page " counter(page) " of " counter(pages); font: 7pt "DejaVu Sans", sans-serif; }
}
html { background: #fff; color: #000; }
body { margin: 0; font: 8.5pt/1.25 "DejaVu Sans", "Liberation Sans", Arial, sans-serif; }
h1 { font-size: 15pt; margin: 0; }
h2 { font-size: 9.5pt; margin: 2mm 0 0.8mm; padding-bottom: 0.4mm; border-bottom: 0.8pt solid #000; break-after: avoid; }
p { margin: 1mm 0; }
.title { display: flex; justify-content: space-between; align-items: flex-start; border-bottom: 1.6pt solid #000; padding-bottom: 2mm; }
.subtitle { margin-top: 1mm; }
table { border-collapse: collapse; width: 100%; }
th, td { text-align: left; vertical-align: top; padding: 0.5mm 1.2mm; }
.ids { width: auto; flex: none; margin-left: 6mm; white-space: nowrap; }
.ids th { font-weight: normal; padding-left: 0; }
.ids td { font-weight: bold; }
.kv th { width: 36mm; font-weight: bold; padding-left: 0; }
.grid th, .grid td { border: 0.5pt solid #000; }
.grid thead th { font-weight: bold; }
.num { text-align: right; white-space: nowrap; font-variant-numeric: tabular-nums; }
.budget { font-size: 6.3pt; line-height: 1.1; }
.budget td, .budget th { padding: 0 0.8mm; }
.budget td:first-child { white-space: nowrap; }
.date { white-space: nowrap; }
.total td { font-weight: bold; }
.mono { font-family: "DejaVu Sans Mono", monospace; font-size: 7.5pt; white-space: nowrap; }
.small { font-size: 7.2pt; line-height: 1.15; }
.verdict { font-size: 10pt; border: 1pt solid #000; padding: 1.5mm 2mm; margin-top: 2mm; }
ul.notes { margin: 0.5mm 0; padding-left: 4mm; font-size: 6pt; line-height: 1.12; }
ul.notes li { margin-bottom: 0.2mm; }
section { break-inside: avoid; }
section.notes-section { break-inside: auto; }
.svg svg { width: 100%; height: auto; display: block; }
.lab { margin: 0 0 1.5mm; font-size: 8pt; }
.equipment { margin-top: 1.5mm; font-size: 6.5pt; }
.equipment td, .equipment th { padding: 0.2mm 1mm; }
.brackets { margin-top: 1.5mm; }
.signatures td { border: 0.5pt solid #000; width: 33%; }
.signatures tr.blank td { height: 9mm; vertical-align: bottom; font-size: 7pt; }
"#;

/// The whole document and the numbers it prints.
///
/// # Errors
/// As the sections: a non-finite number, the figure failing.
pub(super) fn page(c: &Context<'_>) -> Result<(String, Printed), CertificateError> {
    let mut p = Printed::default();
    let title = sections::title(c, &mut p);
    let item = sections::item(c, &mut p);
    let method = sections::method(c, &mut p);
    let conditions = sections::conditions(c, &mut p)?;
    let results = sections::results(c, &mut p)?;
    let decision = sections::decision(c, &mut p)?;
    let authorization = sections::authorization(c, &mut p);
    let budget = super::gum::section(c, &mut p)?;
    let residuals = sections::residuals(c, &mut p)?;
    let traceability = super::trace::section(c, &mut p)?;
    let notes = sections::notes(c, &mut p);
    // The number's characters are letters, digits and '-' (issuer::new_number): nothing
    // in it can end the CSS string; anything else is left out of the page's foot.
    let id: String = c
        .subject
        .number
        .chars()
        .filter(|ch| ch.is_ascii_alphanumeric() || *ch == '-')
        .collect();
    let html = format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>Calibration certificate no. {id}</title>\
         <style>{STYLE}@page {{ @bottom-left {{ content: \"Calibration certificate no. {id}\"; \
         font: 7pt \"DejaVu Sans\", sans-serif; }} }}</style></head><body>\n\
         {title}\n{item}\n{method}\n{conditions}\n{results}\n{decision}\n{authorization}\n\
         {budget}\n{residuals}\n{traceability}\n{notes}\n</body></html>\n"
    );
    refuse_non_finite_words(&html)?;
    Ok((html, p))
}

/// Refuses a document that prints `NaN` or `inf` anywhere: every number of the
/// certificate's own is checked where it is formatted, and this catches one inside a
/// text it quotes (a note, a warning).
fn refuse_non_finite_words(html: &str) -> Result<(), CertificateError> {
    for word in html.split(|c: char| !c.is_ascii_alphanumeric()) {
        if matches!(word, "NaN" | "inf") {
            // The word's place in the document (a split's piece lies inside it).
            let at = word.as_ptr() as usize - html.as_ptr() as usize;
            let before: Vec<char> = html[..at].chars().rev().take(40).collect();
            let before: String = before.into_iter().rev().collect();
            let after: String = html[at..].chars().take(word.len() + 40).collect();
            return Err(CertificateError::NotFinite {
                what: format!("a number in the text '…{before}{after}…'"),
                value: f64::NAN,
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_nan_inside_a_quoted_text_is_refused() {
        for bad in ["<li>u NaN deg</li>", "<li>drift +inf K</li>", "(inf)"] {
            assert!(refuse_non_finite_words(bad).is_err(), "{bad}");
        }
        for good in ["information", "infinite", "NaNo", "<li>u 0.0004 deg</li>"] {
            assert!(refuse_non_finite_words(good).is_ok(), "{good}");
        }
    }
}
