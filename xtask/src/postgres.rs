//! `cargo xtask postgres start|stop`: a throwaway PostgreSQL cluster under
//! `target/postgres` for the history's PostgreSQL tests. `start` makes a fresh cluster
//! (initdb: it listens on a unix socket in `target/postgres/socket`, trusted, and on
//! 127.0.0.1 only, where it asks for a password, SCRAM-SHA-256), starts it on a free
//! local port, creates the database `zerocal_test` and prints its URL on stdout (the
//! only thing printed there, so `.ci/run` can export it as `ZEROCAL_TEST_POSTGRES`).
//! The URL holds no password: a fresh random one is in the password file
//! `target/postgres/pgpass` (owner-only), which the tests find through `PGPASSFILE`, as
//! a plant's technician keeps theirs (docs/history.md). `stop` stops it.
//!
//! The server offers TLS (`ssl=on`) with a certificate for `127.0.0.1` signed by a
//! certificate authority made afresh at each start (rcgen); the authority's certificate
//! is `target/postgres/ca.pem`, for the tests' `sslrootcert`. The URL names no
//! `sslmode`: the default, `prefer`, takes TLS where the server offers it, and a
//! client that has no TLS (the web tests' own connections) still connects.
//!
//! PostgreSQL refuses to run as root: as root, the cluster's directory is handed to the
//! `postgres` user (made by Debian's package) and every server command runs through
//! `runuser -u postgres --`; anyone else runs them directly. The binaries are Debian's,
//! under `/usr/lib/postgresql/N/bin` (the newest N installed).

use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{bail, Context, Result};

use crate::toolchain::{is_root, provision_postgres};

/// Where Debian installs each major version's server binaries.
const DEBIAN_POSTGRES_LIB: &str = "/usr/lib/postgresql";
/// util-linux's `runuser`, by absolute path (Debian: `/usr/sbin`).
const RUNUSER: &str = "/usr/sbin/runuser";
/// The user Debian's package makes for the server.
const SERVER_USER: &str = "postgres";
/// The database the tests connect to (they create their own beside it).
pub const TEST_DATABASE: &str = "zerocal_test";

/// The newest `/usr/lib/postgresql/N/bin` that has `initdb` and `pg_ctl`.
///
/// # Errors
/// No PostgreSQL server installed there.
pub fn bin_dir() -> Result<PathBuf> {
    let entries = std::fs::read_dir(DEBIAN_POSTGRES_LIB).with_context(|| {
        format!("no PostgreSQL server in {DEBIAN_POSTGRES_LIB}: run `cargo xtask setup`")
    })?;
    let mut versions: Vec<(u32, PathBuf)> = entries
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let major = e.file_name().to_str()?.parse::<u32>().ok()?;
            let bin = e.path().join("bin");
            (bin.join("initdb").exists() && bin.join("pg_ctl").exists()).then_some((major, bin))
        })
        .collect();
    versions.sort();
    match versions.pop() {
        Some((_, bin)) => Ok(bin),
        None => bail!(
            "no PostgreSQL server binaries (initdb, pg_ctl) under {DEBIAN_POSTGRES_LIB}/N/bin: \
             run `cargo xtask setup`"
        ),
    }
}

struct Cluster {
    dir: PathBuf,
    bin: PathBuf,
    as_root: bool,
}

impl Cluster {
    fn new(repo: &Path) -> Result<Cluster> {
        Ok(Cluster {
            dir: repo.join("target").join("postgres"),
            bin: bin_dir()?,
            as_root: is_root(),
        })
    }

    fn data(&self) -> PathBuf {
        self.dir.join("data")
    }

    fn socket(&self) -> PathBuf {
        self.dir.join("socket")
    }

    /// `tool` of the server's bin directory, as the server's user when we are root.
    fn command(&self, tool: &str) -> Command {
        let path = self.bin.join(tool);
        if self.as_root {
            let mut c = Command::new(RUNUSER);
            c.args(["-u", SERVER_USER, "--"]).arg(path);
            c
        } else {
            Command::new(path)
        }
    }

    fn run(&self, tool: &str, args: &[&str]) -> Result<()> {
        let mut c = self.command(tool);
        c.args(args);
        // Progress goes to stderr: stdout carries the URL alone.
        let out = c.output().with_context(|| format!("cannot run {c:?}"))?;
        eprint!("{}", String::from_utf8_lossy(&out.stdout));
        eprint!("{}", String::from_utf8_lossy(&out.stderr));
        if !out.status.success() {
            bail!("{c:?} failed ({})", out.status);
        }
        Ok(())
    }

    fn running(&self) -> bool {
        self.data().join("postmaster.pid").exists()
    }

    fn stop(&self) -> Result<()> {
        if !self.running() {
            eprintln!("xtask: no PostgreSQL running in {}", self.data().display());
            return Ok(());
        }
        let data = path_str(&self.data())?;
        self.run("pg_ctl", &["-D", &data, "-m", "fast", "-w", "stop"])
    }

    fn start(&self) -> Result<String> {
        if self.running() {
            self.stop()?;
        }
        if self.dir.exists() {
            std::fs::remove_dir_all(&self.dir)
                .with_context(|| format!("cannot remove {}", self.dir.display()))?;
        }
        std::fs::create_dir_all(self.socket())
            .with_context(|| format!("cannot make {}", self.socket().display()))?;
        // The superuser's password, for initdb to set (then removed).
        let password = fresh_password()?;
        let pwfile = self.dir.join("pwfile");
        write_owner_only(&pwfile, &format!("{password}\n"))?;
        let tls = self.dir.join("tls");
        write_certificates(&tls, &self.dir.join(CA_FILE))?;
        if self.as_root {
            let status = Command::new("/usr/bin/chown")
                .args(["-R", &format!("{SERVER_USER}:")])
                .arg(&self.dir)
                .status()
                .context("cannot run /usr/bin/chown")?;
            if !status.success() {
                bail!("chown of {} to {SERVER_USER} failed", self.dir.display());
            }
        }
        let data = path_str(&self.data())?;
        let socket = path_str(&self.socket())?;
        let log = path_str(&self.dir.join("server.log"))?;
        // A throwaway cluster: no fsync (the tests kill clients, not the server).
        self.run(
            "initdb",
            &[
                "-D",
                &data,
                "-U",
                SERVER_USER,
                "--auth-local=trust",
                "--auth-host=scram-sha-256",
                &format!("--pwfile={}", path_str(&pwfile)?),
                "--encoding=UTF8",
                "--no-sync",
            ],
        )?;
        std::fs::remove_file(&pwfile)
            .with_context(|| format!("cannot remove {}", pwfile.display()))?;
        let port = free_port()?;
        let options = format!(
            "-k {socket} -p {port} -c listen_addresses=127.0.0.1 -c fsync=off \
             -c ssl=on -c ssl_cert_file={} -c ssl_key_file={}",
            path_str(&tls.join("server.crt"))?,
            path_str(&tls.join("server.key"))?
        );
        self.run(
            "pg_ctl",
            &["-D", &data, "-l", &log, "-w", "-o", &options, "start"],
        )?;
        let port = port.to_string();
        self.run(
            "createdb",
            &["-h", &socket, "-p", &port, "-U", SERVER_USER, TEST_DATABASE],
        )?;
        let pgpass = self.dir.join("pgpass");
        write_owner_only(
            &pgpass,
            &format!("127.0.0.1:{port}:*:{SERVER_USER}:{password}\n"),
        )?;
        eprintln!(
            "xtask: the password is in {} (PGPASSFILE={} for the tests)",
            pgpass.display(),
            pgpass.display()
        );
        eprintln!(
            "xtask: TLS offered; the server's certificate authority is {} (sslrootcert=)",
            self.dir.join(CA_FILE).display()
        );
        Ok(format!(
            "postgresql://{SERVER_USER}@127.0.0.1:{port}/{TEST_DATABASE}"
        ))
    }
}

/// The test server's certificate authority, under the cluster's directory (PEM).
pub const CA_FILE: &str = "ca.pem";

/// A fresh certificate authority (its certificate to `ca_file`) and, in `dir`, the
/// server's certificate `server.crt` for `127.0.0.1` signed by it and its key
/// `server.key` (owner-only: the server refuses a key others can read). The
/// authority's key is not kept: nothing else is ever signed by it.
fn write_certificates(dir: &Path, ca_file: &Path) -> Result<()> {
    use rcgen::{
        BasicConstraints, CertificateParams, DnType, IsCa, Issuer, KeyPair, KeyUsagePurpose,
    };
    std::fs::create_dir_all(dir).with_context(|| format!("cannot make {}", dir.display()))?;
    let ca_key = KeyPair::generate().context("cannot make the test CA's key")?;
    let mut ca = CertificateParams::new(Vec::<String>::new())?;
    ca.is_ca = IsCa::Ca(BasicConstraints::Unconstrained);
    ca.distinguished_name
        .push(DnType::CommonName, "zerocal test PostgreSQL CA");
    ca.key_usages = vec![KeyUsagePurpose::KeyCertSign, KeyUsagePurpose::CrlSign];
    let ca_cert = ca.self_signed(&ca_key).context("cannot sign the test CA")?;
    let issuer = Issuer::new(ca, ca_key);
    let key = KeyPair::generate().context("cannot make the test server's key")?;
    // The server listens on 127.0.0.1 alone: that is the name verify-full checks.
    let mut server = CertificateParams::new(vec!["127.0.0.1".to_owned()])?;
    server
        .distinguished_name
        .push(DnType::CommonName, "zerocal test PostgreSQL server");
    let cert = server
        .signed_by(&key, &issuer)
        .context("cannot sign the test server's certificate")?;
    write_owner_only(ca_file, &ca_cert.pem())?;
    write_owner_only(&dir.join("server.crt"), &cert.pem())?;
    write_owner_only(&dir.join("server.key"), &key.serialize_pem())
}

/// 32 hex digits from the kernel's random source.
fn fresh_password() -> Result<String> {
    use std::io::Read as _;
    let mut bytes = [0_u8; 16];
    std::fs::File::open("/dev/urandom")
        .and_then(|mut f| f.read_exact(&mut bytes))
        .context("cannot read /dev/urandom")?;
    Ok(bytes.iter().map(|b| format!("{b:02x}")).collect())
}

/// Writes `text` to `path`, readable by its owner alone (a password file must be).
fn write_owner_only(path: &Path, text: &str) -> Result<()> {
    use std::io::Write as _;
    use std::os::unix::fs::OpenOptionsExt as _;
    let mut f = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .mode(0o600)
        .open(path)
        .with_context(|| format!("cannot make {}", path.display()))?;
    f.write_all(text.as_bytes())
        .with_context(|| format!("cannot write {}", path.display()))
}

fn path_str(p: &Path) -> Result<String> {
    p.to_str()
        .map(str::to_owned)
        .with_context(|| format!("{} is not UTF-8", p.display()))
}

/// A local TCP port nobody listens on now (the OS's choice for port 0).
pub fn free_port() -> Result<u16> {
    let listener = TcpListener::bind("127.0.0.1:0").context("cannot bind a local port")?;
    Ok(listener.local_addr()?.port())
}

/// `cargo xtask setup`'s part: installs Debian's PostgreSQL server when missing and
/// says which is used.
///
/// # Errors
/// Missing and not installable.
pub fn setup() -> Result<()> {
    provision_postgres()?;
    println!("postgres: {}", bin_dir()?.display());
    Ok(())
}

/// `cargo xtask postgres start`: prints the URL of the fresh test database.
///
/// # Errors
/// PostgreSQL missing and not installable, or a server command failing.
pub fn start(repo: &Path) -> Result<()> {
    provision_postgres()?;
    let url = Cluster::new(repo)?.start()?;
    println!("{url}");
    Ok(())
}

/// `cargo xtask postgres stop`.
///
/// # Errors
/// `pg_ctl stop` failing.
pub fn stop(repo: &Path) -> Result<()> {
    Cluster::new(repo)?.stop()
}
