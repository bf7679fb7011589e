//! The PostgreSQL password from where libpq's users keep it, never from the command line:
//! `PGPASSWORD`, else the password file (`PGPASSFILE`, else `~/.pgpass`).
//!
//! A `--db` URL with a password in it is refused ([`crate::DbLocation::from_arg`]): the
//! arguments of a running program are readable by every user of the machine (`ps`,
//! `/proc/PID/cmdline`). The password file's format and rules are libpq's
//! (PostgreSQL documentation, "The Password File"): one `host:port:database:user:password`
//! line per entry, `*` matching anything in the first four fields, `\` escaping `:` and
//! `\`, `#` starting a comment line, the first matching line winning, `localhost`
//! matching a connection over a Unix socket, and the file ignored unless only its owner
//! can read it. Here a file readable by others is refused by name instead of ignored,
//! so that the technician learns why the password was not found.

use crate::error::HistoryError;
use std::path::{Path, PathBuf};

/// libpq's default socket directory: Debian builds it with `/var/run/postgresql`
/// (a link to `/run/postgresql`), upstream with `/tmp`.
const DEFAULT_SOCKET_DIRS: [&str; 3] = ["/var/run/postgresql", "/run/postgresql", "/tmp"];

/// Where the connection goes, as the password file matches it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Target {
    /// Host name, or `localhost` for a Unix socket.
    pub host: String,
    /// Port (5432 by default).
    pub port: u16,
    /// Database (the user's name by default).
    pub database: String,
    /// User name.
    pub user: String,
}

impl Target {
    /// The target of `config`, its defaults filled as libpq fills them (`user`: the
    /// login name from `USER`, else `LOGNAME`).
    pub(crate) fn of(config: &postgres::Config) -> Option<Target> {
        let user = match config.get_user() {
            Some(u) => u.to_owned(),
            None => std::env::var("USER")
                .or_else(|_| std::env::var("LOGNAME"))
                .ok()?,
        };
        let host = match config.get_hosts().first() {
            Some(postgres::config::Host::Tcp(h)) => h.clone(),
            // libpq matches a connection through its default socket directory (or with
            // no host) as `localhost`, any other socket directory by its path.
            Some(postgres::config::Host::Unix(dir))
                if !DEFAULT_SOCKET_DIRS
                    .iter()
                    .any(|d| dir.as_path() == Path::new(d)) =>
            {
                dir.to_string_lossy().into_owned()
            }
            Some(postgres::config::Host::Unix(_)) | None => "localhost".to_owned(),
        };
        Some(Target {
            host,
            port: config.get_ports().first().copied().unwrap_or(5432),
            database: config.get_dbname().unwrap_or(&user).to_owned(),
            user,
        })
    }
}

/// Gives `config` a password where its URL has none (or an empty one): `env_password`
/// (`PGPASSWORD`) if set and not empty, and then the password file is not even read (as
/// libpq); else the first matching line of the password file at `file`, if it exists,
/// with the user it was searched for set as the one to connect as.
///
/// # Errors
/// The password file can be read by others, or cannot be read.
pub(crate) fn fill(
    config: &mut postgres::Config,
    env_password: Option<String>,
    file: Option<&Path>,
) -> Result<(), HistoryError> {
    if config.get_password().is_some_and(|p| !p.is_empty()) {
        return Ok(());
    }
    if let Some(p) = env_password.filter(|p| !p.is_empty()) {
        config.password(p);
        return Ok(());
    }
    let Some(target) = Target::of(config) else {
        return Ok(());
    };
    config.user(&target.user);
    let text = match file {
        Some(path) => read_file(path)?,
        None => None,
    };
    if let Some(p) = text.as_deref().and_then(|t| password(&target, t)) {
        config.password(p);
    }
    Ok(())
}

/// The password of the first line of the password file's `text` that matches `target`.
fn password(target: &Target, text: &str) -> Option<String> {
    text.lines().find_map(|line| matching(line, target))
}

/// The password of `line` if it matches `target`.
fn matching(line: &str, target: &Target) -> Option<String> {
    if line.starts_with('#') {
        return None;
    }
    let fields = split(line)?;
    let [host, port, database, user, password] = fields;
    let port_text = target.port.to_string();
    let fits = |pattern: &str, value: &str| pattern == "*" || pattern == value;
    (fits(&host, &target.host)
        && fits(&port, &port_text)
        && fits(&database, &target.database)
        && fits(&user, &target.user))
    .then_some(password)
}

/// The five fields of a line, `\:` and `\\` unescaped; `None` for a line that has not
/// five (libpq skips it). As libpq reads it, the password ends at its first unescaped
/// `:` and a backslash that ends the line is kept.
fn split(line: &str) -> Option<[String; 5]> {
    let mut fields: Vec<String> = vec![String::new()];
    let mut chars = line.chars();
    while let Some(c) = chars.next() {
        match c {
            '\\' => fields.last_mut()?.push(chars.next().unwrap_or('\\')),
            ':' if fields.len() < 5 => fields.push(String::new()),
            ':' => break,
            c => fields.last_mut()?.push(c),
        }
    }
    fields.try_into().ok()
}

/// The password file's path: `PGPASSFILE`, else `$HOME/.pgpass`.
pub(crate) fn file_path() -> Option<PathBuf> {
    match std::env::var_os("PGPASSFILE").filter(|p| !p.is_empty()) {
        Some(p) => Some(PathBuf::from(p)),
        None => std::env::var_os("HOME")
            .filter(|h| !h.is_empty())
            .map(|h| PathBuf::from(h).join(".pgpass")),
    }
}

/// The password file's text, if it exists; refused if others can read it (libpq
/// ignores such a file; here the technician is told).
///
/// # Errors
/// The file is readable by its group or others, or cannot be read.
pub(crate) fn read_file(path: &Path) -> Result<Option<String>, HistoryError> {
    let named = |e: std::io::Error| {
        HistoryError::BadLocation(format!("the password file {}: {e}", path.display()))
    };
    let meta = match std::fs::metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(named(e)),
    };
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = meta.permissions().mode();
        if mode & 0o077 != 0 {
            return Err(HistoryError::BadLocation(format!(
                "the password file {} can be read by others (mode {:o}): make it the owner's alone (chmod 600 {}), as PostgreSQL requires",
                path.display(),
                mode & 0o777,
                path.display()
            )));
        }
    }
    #[cfg(not(unix))]
    let _ = meta;
    std::fs::read_to_string(path).map(Some).map_err(named)
}

/// Whether the URL carries a (non-empty) password, in `user:password@` or in its query
/// (`?password=`, percent-encoded or not), as the client would read it. A URL the
/// client cannot parse (an option it does not know) is read here by hand: a password
/// beside an unknown option is still a password on the command line.
pub(crate) fn url_has_password(url: &str) -> bool {
    // The TLS options first: the client does not know verify-ca or sslrootcert.
    match crate::pgtls::without_tls_options(url).parse::<postgres::Config>() {
        Ok(c) => c.get_password().is_some_and(|p| !p.is_empty()),
        Err(_) => written_password(url),
    }
}

/// A non-empty password in `url`'s `user:password@` or its query's `password` key
/// (the key percent-decoded, as the client reads it).
fn written_password(url: &str) -> bool {
    let rest = url.split_once("://").map_or(url, |(_, r)| r);
    let authority = rest.split(['/', '?']).next().unwrap_or("");
    let in_userinfo = authority
        .rsplit_once('@')
        .and_then(|(userinfo, _)| userinfo.split_once(':'))
        .is_some_and(|(_, password)| !password.is_empty());
    let in_query = url.split_once('?').is_some_and(|(_, query)| {
        query.split('&').any(|pair| {
            let (key, value) = pair.split_once('=').unwrap_or((pair, ""));
            crate::pgtls::percent_decoded(key) == "password" && !value.is_empty()
        })
    });
    in_userinfo || in_query
}

#[cfg(test)]
mod tests {
    use super::*;

    fn target() -> Target {
        Target {
            host: "db.plant".into(),
            port: 5432,
            database: "zerocal".into(),
            user: "zc".into(),
        }
    }

    /// libpq's rules: the first matching line wins, `*` matches any field, a comment
    /// or short line is skipped, escapes are undone, the password ends at a colon.
    #[test]
    fn the_first_matching_line_gives_the_password() {
        let text = "# plant history\n\
                    other:5432:zerocal:zc:wrong-host\n\
                    db.plant:5433:*:zc:wrong-port\n\
                    too:few:fields\n\
                    db.plant:*:zerocal:zc:s3c:r\\:et\n\
                    *:*:*:*:later\n";
        let file = text;
        // libpq's password is `s3c`: it ends at the first unescaped colon.
        assert_eq!(password(&target(), file).as_deref(), Some("s3c"));
        let mut other = target();
        other.user = "reader".into();
        assert_eq!(password(&other, file).as_deref(), Some("later"));
        assert_eq!(password(&target(), "# none\n"), None);
    }

    /// What `postgres_config` does with a URL without a password: PGPASSWORD first,
    /// the file not even read then (a file others can read does no harm); an empty
    /// PGPASSWORD counts as none; the user searched for is the one connected as.
    #[cfg(unix)]
    #[test]
    fn pgpassword_comes_first_and_an_empty_one_is_none() {
        use std::os::unix::fs::PermissionsExt;
        let dir = std::env::temp_dir().join(format!("zerocal-fill-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(".pgpass");
        std::fs::write(&path, "*:*:*:zc:from-file\n").unwrap();
        let url = "postgres://db.plant/zerocal?user=zc";
        let filled = |env: Option<&str>| {
            let mut c: postgres::Config = url.parse().unwrap();
            fill(&mut c, env.map(str::to_owned), Some(&path)).map(|()| c)
        };
        let pw = |c: &postgres::Config| c.get_password().map(<[u8]>::to_vec);
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o644)).unwrap();
        let c = filled(Some("from-env")).unwrap();
        assert_eq!(pw(&c), Some(b"from-env".to_vec()));
        assert!(
            filled(Some("")).is_err(),
            "an empty PGPASSWORD reads the file"
        );
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o600)).unwrap();
        let c = filled(Some("")).unwrap();
        assert_eq!(
            (pw(&c), c.get_user()),
            (Some(b"from-file".to_vec()), Some("zc"))
        );
        let mut in_url: postgres::Config = "postgres://zc:given@db/zerocal".parse().unwrap();
        fill(&mut in_url, Some("from-env".into()), Some(&path)).unwrap();
        assert_eq!(pw(&in_url), Some(b"given".to_vec()));
        let mut none: postgres::Config = url.parse().unwrap();
        fill(&mut none, None, Some(&dir.join("absent"))).unwrap();
        assert_eq!(pw(&none), None);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn an_escaped_backslash_and_host_field_match() {
        let mut t = target();
        t.host = "a:b".into();
        let text = "a\\:b:5432:zerocal:zc:p\\\\w\\:x\n";
        assert_eq!(password(&t, text).as_deref(), Some("p\\w:x"));
        // A backslash that ends the line stays.
        let text = "*:*:*:*:pw\\\n";
        assert_eq!(password(&t, text).as_deref(), Some("pw\\"));
    }

    #[test]
    fn a_password_in_the_url_is_seen() {
        assert!(url_has_password("postgres://zc:s3cret@db/zerocal"));
        assert!(url_has_password(
            "postgres://zc@db/zerocal?sslmode=disable&password=x"
        ));
        // Percent-encoded keys are decoded by the client: still a password.
        assert!(url_has_password("postgres://zc@db/zerocal?pass%77ord=x"));
        // Beside options only zerocal reads (not the client).
        assert!(url_has_password(
            "postgres://zc:s3cret@db/zerocal?sslmode=verify-full&sslrootcert=%2Fca.pem"
        ));
        assert!(url_has_password(
            "postgres://zc@db/zerocal?sslmode=verify-ca&password=x&sslcert=c"
        ));
        // Beside an option the client does not know (it cannot parse the URL).
        assert!(url_has_password(
            "postgres://zc@db/z?gssencmode=disable&password=s3cret"
        ));
        assert!(url_has_password("postgres://zc:s3cret@db/z?service=plant"));
        assert!(!url_has_password("postgres://zc@db/z?service=plant"));
        // An empty one is none, as for libpq.
        assert!(!url_has_password("postgresql://zc:@db/zerocal"));
        assert!(!url_has_password("postgres://zc@db:5432/zerocal"));
        assert!(!url_has_password("postgres://db/zerocal?user=zc"));
    }

    /// The target's fields from a URL, libpq's defaults where it names none.
    #[test]
    fn the_target_takes_the_urls_fields_and_libpqs_defaults() {
        let c: postgres::Config = "postgres://zc@db.plant:5433/hist".parse().unwrap();
        assert_eq!(
            Target::of(&c),
            Some(Target {
                host: "db.plant".into(),
                port: 5433,
                database: "hist".into(),
                user: "zc".into()
            })
        );
        // The default socket directory is `localhost`, another one its path (libpq).
        let c: postgres::Config = "postgres://zc@%2Fvar%2Frun%2Fpostgresql/hist"
            .parse()
            .unwrap();
        let t = Target::of(&c).unwrap();
        assert_eq!(
            (t.host.as_str(), t.port, t.database.as_str()),
            ("localhost", 5432, "hist")
        );
        let c: postgres::Config = "postgres://zc@%2Fsrv%2Fsock/hist".parse().unwrap();
        assert_eq!(Target::of(&c).map(|t| t.host), Some("/srv/sock".into()));
        let c: postgres::Config = "postgres://zc@db".parse().unwrap();
        assert_eq!(Target::of(&c).map(|t| t.database), Some("zc".into()));
    }

    #[cfg(unix)]
    #[test]
    fn a_password_file_others_can_read_is_refused_by_name() {
        use std::os::unix::fs::PermissionsExt;
        let dir = std::env::temp_dir().join(format!("zerocal-pgpass-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(".pgpass");
        std::fs::write(&path, "*:*:*:*:p\n").unwrap();
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o644)).unwrap();
        let err = read_file(&path).unwrap_err().to_string();
        assert!(
            err.contains("chmod 600") && err.contains(".pgpass"),
            "{err}"
        );
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o600)).unwrap();
        assert_eq!(read_file(&path).unwrap().as_deref(), Some("*:*:*:*:p\n"));
        assert_eq!(read_file(&dir.join("none")).unwrap(), None);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
