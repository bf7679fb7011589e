//! Numeric command-line values with a stated range.
//!
//! Every numeric option of every subcommand parses through one of these, and its help
//! states the same interval (`Range: [0, 1] deg`), so a value outside it (0 where 0 is
//! meaningless, a negative, 1e308, NaN, ±inf) is a named error with exit status 2 before
//! anything runs, never a panic, a hang or a silently odd number.
//! `tests/option_walk.rs` reads each stated range back from `--help` and walks every
//! option through those values.

use clap::builder::TypedValueParser;
use clap::error::ErrorKind;
use std::ffi::OsStr;
use std::fmt;

/// Parses the command line of `P` with every command and subcommand taking a
/// negative number as a value (`--noise-deg -1`, as `--noise-deg=-1`), so it reaches
/// the option's range check and its message instead of being taken for a flag.
/// A parse error exits as clap's do (status 2, naming the option).
pub fn parse<P: clap::Parser>() -> P {
    let matches = negative_numbers(P::command()).get_matches();
    P::from_arg_matches(&matches).unwrap_or_else(|e| e.exit())
}

/// `cmd` and all its subcommands, each numeric option taking a value that starts
/// with `-` (`-1`, and `-inf`, which clap's own negative-number test does not take
/// for a number), so that its range check refuses it by name.
pub fn negative_numbers(cmd: clap::Command) -> clap::Command {
    cmd.allow_negative_numbers(true)
        .mut_args(|a| {
            if is_numeric(&a) {
                a.allow_hyphen_values(true)
            } else {
                a
            }
        })
        .mut_subcommands(negative_numbers)
}

/// Whether an option parses into a number or a pair of numbers (the types of
/// [`RealIn`], [`CountIn`] and [`PairIn`]).
fn is_numeric(a: &clap::Arg) -> bool {
    use std::any::TypeId;
    let t = a.get_value_parser().type_id();
    [
        TypeId::of::<f64>(),
        TypeId::of::<(f64, f64)>(),
        TypeId::of::<u8>(),
        TypeId::of::<u16>(),
        TypeId::of::<u32>(),
        TypeId::of::<u64>(),
        TypeId::of::<usize>(),
        TypeId::of::<i64>(),
    ]
    .into_iter()
    .any(|id| t == id)
}

/// The sensor's reading convention: `rpy` or `axis` (docs/method.md), listed in the help.
pub fn convention() -> impl TypedValueParser<Value = zerocal_core::model::Convention> {
    clap::builder::PossibleValuesParser::new(["rpy", "axis"])
        .try_map(|name| name.parse::<zerocal_core::model::Convention>())
}

/// The planner's criterion: `a` or `d`, listed in the help.
pub fn criterion() -> impl TypedValueParser<Value = zerocal_core::plan::Criterion> {
    clap::builder::PossibleValuesParser::new(["a", "d"])
        .try_map(|name| name.parse::<zerocal_core::plan::Criterion>())
}

/// Seeds: any `u64`.
pub const SEED: CountIn<u64> = CountIn::new(0, u64::MAX);

/// A record of the history: its ID, from 1.
pub const RECORD_ID: CountIn<i64> = CountIn::new(1, i64::MAX as u64);

/// A base tilt or a sensor bias, per axis: a robot base tilted more than 10° is not
/// standing on its foundation, and the SCL3300's offset is at most ±1.15°.
pub const TILT_PAIR: PairIn = PairIn(RealIn::closed(-10.0, 10.0, "deg"));

/// A condition-number limit: above 1e5 a pose set is rank deficient whatever the limit
/// (`zerocal_core::stage2::RANK_DEFICIENT_CONDITION`).
pub const CONDITION: RealIn = RealIn::above(1.0, 1e5, "");

/// A closed or half-open interval of finite reals, with the unit shown in messages.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RealIn {
    lo: f64,
    lo_open: bool,
    hi: f64,
    hi_open: bool,
    unit: &'static str,
}

impl RealIn {
    /// `[lo, hi]`.
    pub const fn closed(lo: f64, hi: f64, unit: &'static str) -> Self {
        RealIn {
            lo,
            lo_open: false,
            hi,
            hi_open: false,
            unit,
        }
    }

    /// `(lo, hi]`: for quantities that must be positive.
    pub const fn above(lo: f64, hi: f64, unit: &'static str) -> Self {
        RealIn {
            lo,
            lo_open: true,
            hi,
            hi_open: false,
            unit,
        }
    }

    /// Whether `v` lies inside (NaN never does).
    pub fn contains(&self, v: f64) -> bool {
        let above_lo = if self.lo_open {
            v > self.lo
        } else {
            v >= self.lo
        };
        let below_hi = if self.hi_open {
            v < self.hi
        } else {
            v <= self.hi
        };
        above_lo && below_hi
    }

    /// Parses and checks one number.
    ///
    /// # Errors
    /// Not a number, or outside the interval: the message states the interval.
    pub fn check(&self, text: &str) -> Result<f64, String> {
        let v: f64 = text
            .trim()
            .parse()
            .map_err(|_| format!("'{text}' is not a number; must be in {self}"))?;
        if self.contains(v) {
            Ok(v)
        } else {
            Err(format!("{v} is outside the range; must be in {self}"))
        }
    }
}

impl fmt::Display for RealIn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}{}, {}{}",
            if self.lo_open { '(' } else { '[' },
            self.lo,
            self.hi,
            if self.hi_open { ')' } else { ']' }
        )?;
        if !self.unit.is_empty() {
            write!(f, " {}", self.unit)?;
        }
        Ok(())
    }
}

impl TypedValueParser for RealIn {
    type Value = f64;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<f64, clap::Error> {
        self.check(&value.to_string_lossy())
            .map_err(|message| invalid(cmd, arg, value, &message))
    }
}

/// An inclusive interval of integers, parsed into `T`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CountIn<T> {
    lo: u64,
    hi: u64,
    _into: std::marker::PhantomData<fn() -> T>,
}

impl<T> CountIn<T> {
    /// `[lo, hi]`.
    pub const fn new(lo: u64, hi: u64) -> Self {
        CountIn {
            lo,
            hi,
            _into: std::marker::PhantomData,
        }
    }

    /// Parses and checks one integer.
    ///
    /// # Errors
    /// Not an integer, or outside the interval: the message states the interval.
    pub fn check(&self, text: &str) -> Result<u64, String> {
        let v: u64 = text
            .trim()
            .parse()
            .map_err(|_| format!("'{text}' is not a whole number; must be in {self}"))?;
        if (self.lo..=self.hi).contains(&v) {
            Ok(v)
        } else {
            Err(format!("{v} is outside the range; must be in {self}"))
        }
    }
}

impl<T> fmt::Display for CountIn<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{}, {}]", self.lo, self.hi)
    }
}

impl<T> TypedValueParser for CountIn<T>
where
    T: TryFrom<u64> + Clone + Send + Sync + 'static,
{
    type Value = T;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<T, clap::Error> {
        let v = self
            .check(&value.to_string_lossy())
            .map_err(|message| invalid(cmd, arg, value, &message))?;
        T::try_from(v).map_err(|_| invalid(cmd, arg, value, "too large for this machine"))
    }
}

/// Two numbers `X,Y`, each in the same interval (a base tilt, a sensor bias).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairIn(pub RealIn);

impl PairIn {
    /// Parses and checks `X,Y`.
    ///
    /// # Errors
    /// Not two numbers, or either outside the interval.
    pub fn check(&self, text: &str) -> Result<(f64, f64), String> {
        let mut it = text.split(',');
        match (it.next(), it.next(), it.next()) {
            (Some(a), Some(b), None) => Ok((self.0.check(a)?, self.0.check(b)?)),
            _ => Err(format!(
                "expected two numbers X,Y, got '{text}'; each must be in {}",
                self.0
            )),
        }
    }
}

impl fmt::Display for PairIn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "each {}", self.0)
    }
}

impl TypedValueParser for PairIn {
    type Value = (f64, f64);

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<(f64, f64), clap::Error> {
        self.check(&value.to_string_lossy())
            .map_err(|message| invalid(cmd, arg, value, &message))
    }
}

/// clap's "invalid value" error (exit status 2), naming the option, the value and why.
fn invalid(cmd: &clap::Command, arg: Option<&clap::Arg>, value: &OsStr, why: &str) -> clap::Error {
    let name = arg.map_or_else(|| "the value".to_owned(), |a| format!("'{a}'"));
    clap::Error::raw(
        ErrorKind::ValueValidation,
        format!(
            "invalid value '{}' for {name}: {why}\n",
            value.to_string_lossy()
        ),
    )
    .with_cmd(cmd)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_refuse_non_finite_and_out_of_range() {
        let r = RealIn::above(0.0, 1.0, "deg");
        assert_eq!(r.check("0.5"), Ok(0.5));
        assert_eq!(r.check("1"), Ok(1.0));
        for bad in ["0", "-1", "1e308", "NaN", "inf", "-inf", "x", ""] {
            let e = r.check(bad).unwrap_err();
            assert!(e.contains("(0, 1] deg"), "{bad}: {e}");
        }
        assert!(RealIn::closed(0.0, 1.0, "").check("0").is_ok());
    }

    /// `--a -1` and `--a -inf` as two arguments reach the range check (clap alone
    /// takes them for flags); a text option still does not swallow a flag.
    #[test]
    fn separate_negative_values_reach_the_range_check() {
        let cmd = negative_numbers(
            clap::Command::new("x")
                .arg(
                    clap::Arg::new("a")
                        .long("a")
                        .value_parser(RealIn::above(0.0, 1.0, "deg")),
                )
                .arg(
                    clap::Arg::new("n")
                        .long("n")
                        .value_parser(CountIn::<u8>::new(1, 9)),
                )
                .arg(clap::Arg::new("out").long("out")),
        );
        for (flag, v, range) in [
            ("--a", "-1", "(0, 1] deg"),
            ("--a", "-inf", "(0, 1] deg"),
            ("--n", "-1", "[1, 9]"),
        ] {
            let e = cmd
                .clone()
                .try_get_matches_from(["x", flag, v])
                .unwrap_err();
            assert_eq!(e.kind(), ErrorKind::ValueValidation, "{flag} {v}: {e}");
            assert!(e.to_string().contains(range), "{flag} {v}: {e}");
        }
        let e = cmd
            .try_get_matches_from(["x", "--out", "--a", "0.5"])
            .unwrap_err();
        assert_ne!(e.kind(), ErrorKind::ValueValidation, "{e}");
    }

    #[test]
    fn counts_and_pairs_state_their_range() {
        let c = CountIn::<usize>::new(4, 64);
        assert_eq!(c.check("4"), Ok(4));
        for bad in ["3", "65", "-1", "1e308", "NaN", "4.5"] {
            assert!(c.check(bad).unwrap_err().contains("[4, 64]"), "{bad}");
        }
        let p = PairIn(RealIn::closed(-10.0, 10.0, "deg"));
        assert_eq!(p.check("0.3, -0.5"), Ok((0.3, -0.5)));
        for bad in ["0.3", "1,2,3", "nan,1", "1,inf", "11,0"] {
            assert!(p.check(bad).unwrap_err().contains("[-10, 10] deg"), "{bad}");
        }
    }
}
