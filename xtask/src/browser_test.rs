//! `cargo xtask browser-test [--screenshots DIR]`: the web application (`zerocal
//! serve`, docs/web.md) used as a person uses it, in headless Chromium driven through
//! the DevTools protocol. On a fresh SQLite history, and on a fresh PostgreSQL database
//! when `ZEROCAL_TEST_POSTGRES` names a server (`cargo xtask postgres start`; under
//! `CI=true` it must), it makes a technician, a reviewer, an authorizer and an admin
//! with `zerocal serve --add-user` (the password in `ZEROCAL_NEW_PASSWORD`, never an
//! argument), starts the release `zerocal serve`, and then, each person signed in in
//! turn: the technician uploads two simulated pendant exports (`zerocal simulate
//! --export`) and sees each solved and recorded, finds the robot on the fleet page by
//! its serial and opens its page, and issues the certificate from the record's page
//! (a form); the reviewer checks the session, the
//! authorizer signs it, and each sees the review's new state on the record and on the
//! certificate; the audit log shows every change with who made it; the admin sees the
//! users. Each step names what it expected and what the page showed when it fails, and
//! the failing page is saved as `OUT/failure.png`.
//!
//! `--screenshots DIR` writes each page (sign-in, fleet, robot, upload result, record
//! with its review, certificate, audit log, users) as `DIR/NAME.png`, the whole page
//! at 1 CSS pixel per pixel, from the SQLite run; docs/web.md shows them.
//!
//! Chromium is Debian's, found by [`crate::toolchain::provision`] (installed when
//! missing, as root); `headless_chrome` launches it with a fresh temporary profile, without
//! the sandbox (CI runs as root), and downloads nothing.

use std::io::Read as _;
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::Arc;
use std::time::{Duration, Instant};

use anyhow::{anyhow, bail, Context, Result};
use headless_chrome::protocol::cdp::Page;
use headless_chrome::{Browser, LaunchOptions, Tab};

use crate::toolchain;

/// What `cargo xtask browser-test` is asked.
pub struct Options {
    /// Where the histories, exports, server logs and a failure's screenshot go.
    pub out: PathBuf,
    /// Where the pages' screenshots go, if anywhere.
    pub screenshots: Option<PathBuf>,
}

/// The people of the test: name and `zerocal serve --role`.
const TECHNICIAN: &str = "tina";
const REVIEWER: &str = "ravi";
const AUTHORIZER: &str = "ada";
const ADMIN: &str = "max";
const PEOPLE: [(&str, &str); 4] = [
    (TECHNICIAN, "technician"),
    (REVIEWER, "reviewer"),
    (AUTHORIZER, "authorizer"),
    (ADMIN, "admin"),
];

/// The test accounts' password (of these throwaway histories only).
const PASSWORD: &str = "browser test password";

/// The robots uploaded: serial, built-in profile, the simulation's seed. The first is
/// the one the test follows through review and signature; the second makes the fleet
/// page a fleet, so that finding the first by its serial is a search.
const ROBOTS: [(&str, &str, u64); 2] = [
    ("KR6-0041", "kuka-kr6-r900-sixx", 41),
    ("IRB140-0007", "abb-irb140", 7),
];

/// The certificates' issuer: the tests' (illustrative IDs and dates), as history-demo's.
const ISSUER: &str = "cli/tests/golden/issuer.toml";

/// The days between calibrations the server is started with, so the fleet page shows
/// due dates (an interval is the plant's to choose; this one is the test's).
const INTERVAL_DAYS: &str = "365";

/// How long the server may take to answer after it starts (s).
const SERVER_START_S: u64 = 60;

/// How long one page may take to load or an element to appear (s): a loaded CI
/// machine's cold Chromium and a certificate solved again take seconds, not this.
const PAGE_TIMEOUT_S: u64 = 60;

/// The browser window (CSS pixels): a laptop's screen.
const WINDOW: (u32, u32) = (1100, 800);

/// The database the PostgreSQL run makes afresh beside the test database.
const POSTGRES_DATABASE: &str = "zerocal_browser_test";

/// Runs the test on SQLite and, when `ZEROCAL_TEST_POSTGRES` is set, on PostgreSQL.
///
/// # Errors
/// A tool missing, a build or a command failing, a step of the test failing.
pub fn run(root: &Path, options: &Options) -> Result<()> {
    let tools = toolchain::provision(toolchain::Needs::RENDER, toolchain::ToolchainChoice::Auto)?;
    let chromium = tools.render()?.chromium.clone();
    let out = absolute(root, &options.out);
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    let zerocal = zerocal_binary(root)?;
    let mut exports = Vec::new();
    for (serial, robot, seed) in ROBOTS {
        let export = out.join(format!("{serial}.export"));
        run_ok(
            Command::new(&zerocal)
                .args(["simulate", "--robot", robot, "--seed", &seed.to_string()])
                .arg("--export")
                .arg(&export),
            &format!("zerocal simulate --robot {robot}"),
        )?;
        exports.push(export);
    }
    let mut databases = Vec::new();
    let sqlite = out.join("sqlite");
    if sqlite.exists() {
        std::fs::remove_dir_all(&sqlite).with_context(|| format!("{}", sqlite.display()))?;
    }
    std::fs::create_dir_all(&sqlite)?;
    databases.push((
        "SQLite",
        path_str(&sqlite.join("history.sqlite"))?,
        sqlite.clone(),
    ));
    match std::env::var("ZEROCAL_TEST_POSTGRES") {
        Ok(url) if !url.is_empty() => {
            let dir = out.join("postgres");
            std::fs::create_dir_all(&dir)?;
            databases.push(("PostgreSQL", fresh_postgres_database(&url)?, dir));
        }
        _ => {
            if std::env::var("CI").as_deref() == Ok("true") {
                bail!(
                    "CI=true but ZEROCAL_TEST_POSTGRES is unset: the browser test would skip PostgreSQL"
                );
            }
            println!("browser-test: ZEROCAL_TEST_POSTGRES unset, PostgreSQL not tested");
        }
    }
    let screenshots = match &options.screenshots {
        Some(dir) => {
            let dir = absolute(root, dir);
            std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
            Some(dir)
        }
        None => None,
    };
    for (i, (name, db, dir)) in databases.iter().enumerate() {
        println!("browser-test on {name} ({db})");
        let run = Run {
            root,
            zerocal: &zerocal,
            chromium: &chromium,
            db,
            dir,
            exports: &exports,
            // The pages are the same on both databases: one set of pictures.
            screenshots: if i == 0 { screenshots.as_deref() } else { None },
        };
        run.scenario()
            .with_context(|| format!("browser-test on {name}"))?;
        println!("browser-test on {name}: passed");
    }
    Ok(())
}

/// One run of the scenario on one database.
struct Run<'a> {
    root: &'a Path,
    zerocal: &'a Path,
    chromium: &'a Path,
    /// `--db`'s value.
    db: &'a str,
    /// This run's directory (server log, a failure's screenshot).
    dir: &'a Path,
    exports: &'a [PathBuf],
    screenshots: Option<&'a Path>,
}

impl Run<'_> {
    fn scenario(&self) -> Result<()> {
        for (name, role) in PEOPLE {
            run_ok(
                Command::new(self.zerocal)
                    .args(["serve", "--db", self.db, "--add-user", name, "--role", role])
                    .env("ZEROCAL_NEW_PASSWORD", PASSWORD)
                    .stdin(Stdio::null()),
                &format!("zerocal serve --add-user {name} --role {role}"),
            )?;
        }
        let server = Server::start(self)?;
        let args = [
            std::ffi::OsStr::new("--disable-dev-shm-usage"),
            std::ffi::OsStr::new("--no-first-run"),
            std::ffi::OsStr::new("--hide-scrollbars"),
        ];
        let launch = LaunchOptions::default_builder()
            .path(Some(self.chromium.to_path_buf()))
            .headless(true)
            // CI runs as root, where Chromium's sandbox cannot start.
            .sandbox(false)
            .window_size(Some(WINDOW))
            // No user_data_dir: a fresh temporary profile each launch, no cookie kept.
            .args(args.to_vec())
            .idle_browser_timeout(Duration::from_secs(10 * PAGE_TIMEOUT_S))
            .build()
            .map_err(|e| anyhow!("Chromium's launch options: {e}"))?;
        let browser = Browser::new(launch)
            .map_err(|e| anyhow!("cannot start {}: {e}", self.chromium.display()))?;
        let tab = browser
            .new_tab()
            .map_err(|e| anyhow!("Chromium opened no tab: {e}"))?;
        tab.set_default_timeout(Duration::from_secs(PAGE_TIMEOUT_S));
        let person = Person {
            tab,
            base: format!("http://{}", server.address),
            screenshots: self.screenshots,
        };
        let result = self.steps(&person);
        if result.is_err() {
            let failure = self.dir.join("failure.png");
            if person.screenshot_to(&failure).is_ok() {
                eprintln!("browser-test: the failing page is {}", failure.display());
            }
            eprintln!("browser-test: the server's log is {}", server.log.display());
        }
        drop(browser);
        server.stop()?;
        result
    }

    /// The scenario, each step as a person takes it.
    fn steps(&self, p: &Person) -> Result<()> {
        let (serial, _, _) = ROBOTS[0];
        // Signed out, every page leads to the sign-in.
        p.go("/fleet")?;
        p.expect(
            "the fleet page signed out",
            &["Sign in", "Name", "Password"],
        )?;
        p.refuse("the fleet page signed out", &[serial])?;
        p.screenshot("sign-in")?;

        p.sign_in(TECHNICIAN, "technician")?;
        let mut ids = Vec::new();
        for ((serial, robot, _), export) in ROBOTS.iter().zip(self.exports) {
            p.go("/upload")?;
            p.type_into("input[name=serial]", serial)?;
            let export = path_str(export)?;
            p.tab
                .find_element("input[name=export]")
                .and_then(|e| e.set_input_files(&[export.as_str()]).map(|_| ()))
                .map_err(|e| anyhow!("the upload form's file field: {e}"))?;
            p.click("main form button")?;
            let id = p.record_id_in_url().with_context(|| {
                format!("uploading {robot}'s export as {serial} led to no record's page")
            })?;
            p.expect(
                "the record's page after the upload",
                &[
                    &format!("Record {id}: session of {serial}"),
                    &format!("by {TECHNICIAN}"),
                    "Not checked yet.",
                    "Next: checked, signed by a user with the role reviewer.",
                ],
            )?;
            // The technician may not sign their own record.
            p.count("the technician's record page", "form[action$='/sign']", 0)?;
            ids.push(id);
        }
        let id = ids[0];
        p.go(&format!("/record/{id}"))?;
        p.screenshot("upload-result")?;

        // The fleet: both robots, then the one found by its serial.
        p.go("/fleet")?;
        p.expect(
            "the fleet page",
            &["Fleet: 2 robots", ROBOTS[0].0, ROBOTS[1].0],
        )?;
        p.screenshot("fleet")?;
        p.type_into("input[name=q]", serial)?;
        p.click("main form button")?;
        p.expect(
            "the fleet page searched by serial",
            &["Fleet: 1 robot\n", serial],
        )?;
        p.refuse("the fleet page searched by serial", &[ROBOTS[1].0])?;
        p.click(&format!("a[href='/robot/{serial}']"))?;
        p.expect(
            "the robot's page",
            &[
                &format!("Robot {serial}"),
                "Records",
                "Reducers",
                "Over time",
                "measured",
            ],
        )?;
        p.count("the robot's page plots", "main img", 1..)?;
        p.screenshot("robot")?;
        // The technician issues its certificate from the record's page (a form: a GET
        // issues none).
        p.go(&format!("/record/{id}"))?;
        p.click(&format!("form[action='/record/{id}/certificate'] button"))?;
        p.expect(
            "the certificate before its review",
            &[serial, &format!("Review of record {id}"), "not authorized"],
        )?;
        p.sign_out()?;

        // The reviewer checks it.
        p.sign_in(REVIEWER, "reviewer")?;
        p.go(&format!("/record/{id}"))?;
        p.click("form[action$='/sign'] button")?;
        p.expect(
            "the record after the check",
            &[
                &format!("checked by {REVIEWER}"),
                "Next: authorized, signed by a user with the role authorizer.",
            ],
        )?;
        p.count("the reviewer's record page", "form[action$='/sign']", 0)?;
        p.sign_out()?;

        // The authorizer signs it.
        p.sign_in(AUTHORIZER, "authorizer")?;
        p.go(&format!("/record/{id}"))?;
        p.click("form[action$='/sign'] button")?;
        p.expect(
            "the record after the signature",
            &[
                &format!("checked by {REVIEWER}"),
                &format!("authorized by {AUTHORIZER}"),
                "Authorized.",
            ],
        )?;
        p.count("the signed record's page", "form[action$='/sign']", 0)?;
        p.screenshot("record")?;
        p.click(&format!("a[href='/record/{id}/certificate']"))?;
        p.expect(
            "the signed certificate",
            &[
                serial,
                &format!("measured by {TECHNICIAN}"),
                &format!("checked by {REVIEWER}"),
                &format!("authorized by {AUTHORIZER}"),
            ],
        )?;
        p.refuse("the signed certificate", &["not authorized"])?;
        p.screenshot("certificate")?;

        // Every change, with who made it.
        p.go("/audit")?;
        p.expect(
            "the audit log",
            &[
                "user.add",
                "record.insert",
                "record.sign",
                "certificate.issue",
                TECHNICIAN,
                REVIEWER,
                AUTHORIZER,
                &format!("record {id}"),
            ],
        )?;
        p.screenshot("audit")?;
        p.sign_out()?;

        // The admin's users page.
        p.sign_in(ADMIN, "admin")?;
        p.go("/admin/users")?;
        let names: Vec<&str> = PEOPLE.iter().map(|(n, _)| *n).collect();
        p.expect("the users page", &names)?;
        p.count("the users page's rows", "main table tr", PEOPLE.len() + 1)?;
        p.screenshot("users")?;
        p.sign_out()?;
        Ok(())
    }
}

/// A person at the browser.
struct Person<'a> {
    tab: Arc<Tab>,
    /// `http://127.0.0.1:PORT`.
    base: String,
    screenshots: Option<&'a Path>,
}

/// How many of an element a page should have.
trait Count {
    fn holds(&self, n: usize) -> bool;
    fn describe(&self) -> String;
}

impl Count for usize {
    fn holds(&self, n: usize) -> bool {
        n == *self
    }
    fn describe(&self) -> String {
        self.to_string()
    }
}

impl Count for std::ops::RangeFrom<usize> {
    fn holds(&self, n: usize) -> bool {
        self.contains(&n)
    }
    fn describe(&self) -> String {
        format!("at least {}", self.start)
    }
}

impl Person<'_> {
    fn go(&self, path: &str) -> Result<()> {
        let url = format!("{}{path}", self.base);
        self.mark_page()?;
        self.tab
            .navigate_to(&url)
            .map_err(|e| anyhow!("opening {url}: {e}"))?;
        self.wait_for_new_page(&format!("opening {url}"))
    }

    /// Marks the page shown now, so that [`Person::wait_for_new_page`] can tell the
    /// next one from it (a form posted to the page it came from keeps its URL).
    fn mark_page(&self) -> Result<()> {
        self.tab
            .evaluate("window.zerocalOldPage = true", false)
            .map_err(|e| anyhow!("marking {}: {e}", self.url()))?;
        Ok(())
    }

    /// Waits until a page without the mark has loaded.
    fn wait_for_new_page(&self, after: &str) -> Result<()> {
        let deadline = Instant::now() + Duration::from_secs(PAGE_TIMEOUT_S);
        loop {
            // Between two pages there may be no document to ask: that is not an error.
            let loaded = self
                .tab
                .evaluate(
                    "window.zerocalOldPage === undefined && document.readyState === 'complete'",
                    false,
                )
                .ok()
                .and_then(|r| r.value)
                .and_then(|v| v.as_bool())
                == Some(true);
            if loaded {
                return Ok(());
            }
            if Instant::now() > deadline {
                bail!(
                    "{after}: no new page within {PAGE_TIMEOUT_S} s (still {})",
                    self.url()
                );
            }
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    fn url(&self) -> String {
        self.tab.get_url()
    }

    /// The page's text as a person reads it.
    fn text(&self) -> Result<String> {
        self.tab
            .wait_for_element("body")
            .and_then(|b| b.get_inner_text())
            .map_err(|e| anyhow!("reading {}: {e}", self.url()))
    }

    /// Fails naming each of `wanted` the page does not show.
    fn expect(&self, what: &str, wanted: &[&str]) -> Result<()> {
        let text = self.text()?;
        let missing: Vec<&&str> = wanted.iter().filter(|w| !text.contains(**w)).collect();
        if !missing.is_empty() {
            bail!(
                "{what} ({}) does not show {missing:?}; it shows:\n{text}",
                self.url()
            );
        }
        Ok(())
    }

    /// Fails naming each of `unwanted` the page shows.
    fn refuse(&self, what: &str, unwanted: &[&str]) -> Result<()> {
        let text = self.text()?;
        let shown: Vec<&&str> = unwanted.iter().filter(|w| text.contains(**w)).collect();
        if !shown.is_empty() {
            bail!(
                "{what} ({}) shows {shown:?}, which it should not; it shows:\n{text}",
                self.url()
            );
        }
        Ok(())
    }

    /// Fails unless the page has `count` elements matching `selector`.
    fn count(&self, what: &str, selector: &str, count: impl Count) -> Result<()> {
        // find_elements fails when there is none.
        let n = self.tab.find_elements(selector).map_or(0, |v| v.len());
        if !count.holds(n) {
            bail!(
                "{what} ({}) has {n} of `{selector}`, not {}",
                self.url(),
                count.describe()
            );
        }
        Ok(())
    }

    fn type_into(&self, selector: &str, text: &str) -> Result<()> {
        self.tab
            .wait_for_element(selector)
            .and_then(|e| {
                e.click()
                    .map(|_| ())
                    .and_then(|()| e.type_into(text).map(|_| ()))
            })
            .map_err(|e| anyhow!("typing into `{selector}` on {}: {e}", self.url()))
    }

    /// Clicks what `selector` finds and waits for the page it leads to.
    fn click(&self, selector: &str) -> Result<()> {
        let before = self.url();
        let element = self
            .tab
            .wait_for_element(selector)
            .map_err(|e| anyhow!("no `{selector}` on {before}: {e}"))?;
        self.mark_page()?;
        element
            .click()
            .map_err(|e| anyhow!("clicking `{selector}` on {before}: {e}"))?;
        self.wait_for_new_page(&format!("clicking `{selector}` on {before}"))
    }

    fn sign_in(&self, name: &str, role: &str) -> Result<()> {
        self.go("/login")?;
        self.type_into("input[name=name]", name)?;
        self.type_into("input[name=password]", PASSWORD)?;
        self.click("main form button")?;
        self.expect(
            &format!("the page after {name}'s sign-in"),
            &[&format!("{name} ({role})"), "Sign out", "Fleet"],
        )
    }

    /// Back to the fleet (a certificate is a document of its own, without the
    /// application's menu) and out.
    fn sign_out(&self) -> Result<()> {
        self.go("/fleet")?;
        self.click("nav form button")?;
        self.expect("the page after signing out", &["Sign in"])?;
        self.refuse("the page after signing out", &["Sign out"])
    }

    /// The record's ID in `/record/ID`, the page the upload leads to.
    fn record_id_in_url(&self) -> Result<i64> {
        let url = self.url();
        let id = url
            .rsplit_once("/record/")
            .map(|(_, id)| id)
            .ok_or_else(|| {
                anyhow!(
                    "{url} is not a record's page; it shows:\n{}",
                    self.text().unwrap_or_default()
                )
            })?;
        id.parse()
            .map_err(|_| anyhow!("{url}: '{id}' is not a record's ID"))
    }

    /// The page as `DIR/NAME.png`, when screenshots are asked for.
    fn screenshot(&self, name: &str) -> Result<()> {
        if let Some(dir) = self.screenshots {
            let file = dir.join(format!("{name}.png"));
            self.screenshot_to(&file)?;
            println!("browser-test: {} ({})", file.display(), self.url());
        }
        Ok(())
    }

    /// The whole page, not only the window's part of it, at 1 CSS pixel per pixel.
    fn screenshot_to(&self, file: &Path) -> Result<()> {
        let metrics = self
            .tab
            .call_method(Page::GetLayoutMetrics(None))
            .map_err(|e| anyhow!("the page's size: {e}"))?;
        let size = metrics.css_content_size;
        // The content's own height (the layout's is at least the window's): a short
        // page's picture without the empty window under it.
        let used = self
            .tab
            .evaluate(
                "Math.ceil(document.body.getBoundingClientRect().bottom + 24)",
                false,
            )
            .ok()
            .and_then(|r| r.value)
            .and_then(|v| v.as_f64())
            .unwrap_or(size.height);
        let shot = self
            .tab
            .call_method(Page::CaptureScreenshot {
                format: Some(Page::CaptureScreenshotFormatOption::Png),
                quality: None,
                clip: Some(Page::Viewport {
                    x: 0.0,
                    y: 0.0,
                    width: size.width.max(f64::from(WINDOW.0)),
                    height: used.clamp(1.0, size.height),
                    scale: 1.0,
                }),
                from_surface: Some(true),
                capture_beyond_viewport: Some(true),
                optimize_for_speed: None,
            })
            .map_err(|e| anyhow!("a screenshot of {}: {e}", self.url()))?;
        use base64::Engine as _;
        let png = base64::engine::general_purpose::STANDARD
            .decode(shot.data)
            .context("Chromium's screenshot is not base64")?;
        std::fs::write(file, png).with_context(|| format!("writing {}", file.display()))
    }
}

/// `zerocal serve` on a free local port, stopped (killed) when dropped.
struct Server {
    child: Child,
    address: String,
    log: PathBuf,
}

impl Server {
    fn start(run: &Run) -> Result<Server> {
        let port = crate::postgres::free_port()?;
        let address = format!("127.0.0.1:{port}");
        let log = run.dir.join("server.log");
        let out = std::fs::File::create(&log).with_context(|| format!("{}", log.display()))?;
        let err = out.try_clone()?;
        let child = Command::new(run.zerocal)
            .args(["serve", "--db", run.db, "--listen", &address])
            .args(["--interval-days", INTERVAL_DAYS])
            .arg("--certificate-config")
            .arg(run.root.join(ISSUER))
            .arg("--chromium")
            .arg(run.chromium)
            .stdin(Stdio::null())
            .stdout(out)
            .stderr(err)
            .spawn()
            .with_context(|| format!("cannot run {}", run.zerocal.display()))?;
        let mut server = Server {
            child,
            address,
            log,
        };
        let deadline = Instant::now() + Duration::from_secs(SERVER_START_S);
        loop {
            if TcpStream::connect(&server.address).is_ok() {
                return Ok(server);
            }
            if let Some(status) = server.child.try_wait()? {
                bail!(
                    "zerocal serve stopped ({status}) before it answered: {}",
                    server.log_text()
                );
            }
            if Instant::now() > deadline {
                bail!(
                    "zerocal serve did not answer on {} within {SERVER_START_S} s: {}",
                    server.address,
                    server.log_text()
                );
            }
            std::thread::sleep(Duration::from_millis(100));
        }
    }

    fn log_text(&self) -> String {
        let mut text = String::new();
        let _ = std::fs::File::open(&self.log).and_then(|mut f| f.read_to_string(&mut text));
        text
    }

    /// Stops it; a server that stopped by itself before has failed.
    fn stop(mut self) -> Result<()> {
        if let Some(status) = self.child.try_wait()? {
            bail!(
                "zerocal serve stopped by itself ({status}) during the test: {}",
                self.log_text()
            );
        }
        Ok(())
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Makes [`POSTGRES_DATABASE`] afresh on the server of `url` (the test database's URL,
/// `postgresql://USER@HOST:PORT/DB`, its password in `PGPASSFILE`) with Debian's
/// `psql`, and returns its URL.
fn fresh_postgres_database(url: &str) -> Result<String> {
    let psql = crate::postgres::bin_dir()?.join("psql");
    let (server, _) = url
        .rsplit_once('/')
        .ok_or_else(|| anyhow!("ZEROCAL_TEST_POSTGRES={url} names no database"))?;
    run_ok(
        Command::new(&psql)
            .args([url, "-v", "ON_ERROR_STOP=1", "-q"])
            .args([
                "-c",
                &format!("DROP DATABASE IF EXISTS {POSTGRES_DATABASE} WITH (FORCE)"),
            ])
            .args(["-c", &format!("CREATE DATABASE {POSTGRES_DATABASE}")])
            .stdin(Stdio::null()),
        &format!("psql {url}: making the database {POSTGRES_DATABASE}"),
    )?;
    Ok(format!("{server}/{POSTGRES_DATABASE}"))
}

/// The release `zerocal`, built by cargo (the one that runs xtask), as cargo names it.
fn zerocal_binary(root: &Path) -> Result<PathBuf> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_owned());
    let out = Command::new(cargo)
        .current_dir(root)
        .args([
            "build",
            "--release",
            "-p",
            "zerocal-cli",
            "--bin",
            "zerocal",
            "--message-format=json-render-diagnostics",
        ])
        .stderr(Stdio::inherit())
        .output()
        .context("running cargo build -p zerocal-cli")?;
    if !out.status.success() {
        bail!("cargo build --release -p zerocal-cli failed");
    }
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .filter(|m| m["reason"] == "compiler-artifact" && m["target"]["name"] == "zerocal")
        .find_map(|m| m["executable"].as_str().map(PathBuf::from))
        .ok_or_else(|| anyhow!("cargo built no `zerocal` executable"))
}

/// Runs `command`, failing with its output.
fn run_ok(command: &mut Command, what: &str) -> Result<()> {
    let out = command
        .output()
        .with_context(|| format!("cannot run {what}"))?;
    if !out.status.success() {
        bail!(
            "{what} failed ({}): {}{}",
            out.status,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
    Ok(())
}

fn absolute(root: &Path, p: &Path) -> PathBuf {
    if p.is_absolute() {
        p.to_path_buf()
    } else {
        root.join(p)
    }
}

fn path_str(p: &Path) -> Result<String> {
    p.to_str()
        .map(str::to_owned)
        .with_context(|| format!("{} is not UTF-8", p.display()))
}
