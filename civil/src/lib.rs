//! zerocal's calendar, the one place the desktop turns seconds into dates and checks a
//! date: the history database and the `zerocal` CLI both use it, so a record's date, a
//! certificate's issue date, a bracket calibration's date and a robot program's header
//! are read, checked and written the same way.
//!
//! - [`Date`]: a day of the proleptic Gregorian calendar, read only from the strict
//!   `YYYY-MM-DD` ([`Date::parse`], whose [`DateError`] says what is wrong), written the
//!   same way, and counted in days from 1970-01-01 ([`Date::days`], [`Date::from_days`]).
//! - [`Timestamp`]: a date and a UTC time of day to the second, from Unix seconds,
//!   written as RFC 3339 (`2026-11-27T06:47:25Z`).
//! - [`Timestamp::now`]: `SOURCE_DATE_EPOCH` if it is set (the reproducible-builds
//!   convention: a generated file's header can be made byte for byte again), else the
//!   clock; a value that is set but is not seconds since 1970 is an error
//!   ([`EpochError`]), never silently replaced by the clock.
//!   [`Timestamp::clock`] is the clock alone, for when a thing happens (a session
//!   measured, a bracket calibrated, a certificate issued, a record stored), which no
//!   environment variable may change.
//!
//! No leap seconds (Unix time has none) and no time zones: every date is UTC.
//!
//! zerocal-core's `bracket::check_date` checks a `YYYYMMDD` number on the pendant
//! (`no_std`, firmware); the desktop checks dates here.

use std::fmt;
use std::ops::RangeInclusive;
use std::str::FromStr;

/// Seconds in a day (Unix time has no leap seconds).
pub const SECONDS_PER_DAY: i64 = 86_400;

/// The environment variable that fixes "now" (seconds since 1970-01-01T00:00:00Z).
pub const SOURCE_DATE_EPOCH: &str = "SOURCE_DATE_EPOCH";

/// Whether `year` is a leap year of the Gregorian calendar.
#[must_use]
pub fn is_leap_year(year: i64) -> bool {
    (year % 4 == 0 && year % 100 != 0) || year % 400 == 0
}

/// The days of `month` (1-12) of `year`, `None` for no such month.
#[must_use]
pub fn days_in_month(year: i64, month: u32) -> Option<u32> {
    match month {
        2 if is_leap_year(year) => Some(29),
        2 => Some(28),
        4 | 6 | 9 | 11 => Some(30),
        1 | 3 | 5 | 7 | 8 | 10 | 12 => Some(31),
        _ => None,
    }
}

/// Year, month, day of the day `days` after 1970-01-01 in the proleptic Gregorian
/// calendar (H. Hinnant's `civil_from_days`, public domain,
/// <https://howardhinnant.github.io/date_algorithms.html>). In `i128`, so every `i64`
/// day is exact.
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = i128::from(days) + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i128::from(month <= 2);
    // |year| <= |days| / 365 + 1 fits i64; day is 1..=31 and month 1..=12 by
    // construction.
    (
        i64::try_from(year).unwrap_or(if year < 0 { i64::MIN } else { i64::MAX }),
        month as u32,
        day as u32,
    )
}

/// Days from 1970-01-01 to year-month-day (H. Hinnant's `days_from_civil`, public
/// domain), saturating at the ends of `i64` (years beyond about 2.5e16).
fn days_from_civil(year: i64, month: u32, day: u32) -> i64 {
    let (m, d) = (i128::from(month), i128::from(day));
    let y = i128::from(year) - i128::from(month <= 2);
    let era = y.div_euclid(400);
    let yoe = y.rem_euclid(400);
    let mp = (m + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    let days = era * 146_097 + doe - 719_468;
    i64::try_from(days).unwrap_or(if days < 0 { i64::MIN } else { i64::MAX })
}

/// What is wrong with a date.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DateError {
    /// Not written `YYYY-MM-DD`: four digits, `-`, two digits, `-`, two digits.
    Shape,
    /// A month that is not 1 to 12.
    Month {
        /// The month given.
        month: u32,
    },
    /// A day the month does not have (2026-02-31, 2023-02-29, day 0).
    Day {
        /// The year.
        year: i64,
        /// The month, 1-12.
        month: u32,
        /// The day given.
        day: u32,
    },
    /// A real day, in a year the caller does not take ([`Date::within_years`]).
    Year {
        /// The year given.
        year: i64,
        /// The first year taken.
        first: i64,
        /// The last year taken.
        last: i64,
    },
}

impl fmt::Display for DateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DateError::Shape => write!(f, "not four digits, '-', two digits, '-', two digits"),
            DateError::Month { month } => write!(f, "month {month} is not 1 to 12"),
            DateError::Day { year, month, day } => {
                let days = days_in_month(*year, *month).unwrap_or(0);
                write!(f, "{year:04}-{month:02} has no day {day} (it has {days})")
            }
            DateError::Year { year, first, last } => {
                write!(f, "year {year} is not {first} to {last}")
            }
        }
    }
}

impl std::error::Error for DateError {}

/// A day of the proleptic Gregorian calendar (UTC). Ordered by time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Date {
    year: i64,
    month: u32,
    day: u32,
}

impl Date {
    /// 1970-01-01, day 0.
    pub const EPOCH: Date = Date {
        year: 1970,
        month: 1,
        day: 1,
    };

    /// The date year-month-day, checked.
    ///
    /// # Errors
    /// A month that is not 1 to 12, a day the month does not have.
    pub fn new(year: i64, month: u32, day: u32) -> Result<Date, DateError> {
        let days = days_in_month(year, month).ok_or(DateError::Month { month })?;
        if (1..=days).contains(&day) {
            Ok(Date { year, month, day })
        } else {
            Err(DateError::Day { year, month, day })
        }
    }

    /// The date written `YYYY-MM-DD` (exactly: ten characters, ASCII digits, no sign,
    /// no spaces), checked against the calendar.
    ///
    /// # Errors
    /// Any other shape; a month that is not 1 to 12; a day the month does not have.
    pub fn parse(text: &str) -> Result<Date, DateError> {
        let b = text.as_bytes();
        let shape = b.len() == 10
            && b[4] == b'-'
            && b[7] == b'-'
            && b.iter()
                .enumerate()
                .all(|(i, c)| i == 4 || i == 7 || c.is_ascii_digit());
        if !shape {
            return Err(DateError::Shape);
        }
        let number = |from: usize, to: usize| {
            b[from..to]
                .iter()
                .fold(0u32, |n, c| n * 10 + u32::from(c - b'0'))
        };
        Date::new(i64::from(number(0, 4)), number(5, 7), number(8, 10))
    }

    /// The date of the number `YYYYMMDD` (how the pendant stores a bracket
    /// calibration's date), checked.
    ///
    /// # Errors
    /// A month or day that is no date's.
    pub fn from_yyyymmdd(number: u32) -> Result<Date, DateError> {
        Date::new(
            i64::from(number / 10_000),
            (number / 100) % 100,
            number % 100,
        )
    }

    /// The number `YYYYMMDD` of a date of the years 0 to 9999, `None` for others.
    #[must_use]
    pub fn yyyymmdd(self) -> Option<u32> {
        let year = u32::try_from(self.year).ok().filter(|y| *y <= 9999)?;
        Some(year * 10_000 + self.month * 100 + self.day)
    }

    /// The date itself if its year is within `years`.
    ///
    /// # Errors
    /// [`DateError::Year`] for a year outside them.
    pub fn within_years(self, years: RangeInclusive<i64>) -> Result<Date, DateError> {
        if years.contains(&self.year) {
            Ok(self)
        } else {
            Err(DateError::Year {
                year: self.year,
                first: *years.start(),
                last: *years.end(),
            })
        }
    }

    /// The day `days` after 1970-01-01 (before it if negative); the inverse of
    /// [`Date::days`].
    #[must_use]
    pub fn from_days(days: i64) -> Date {
        let (year, month, day) = civil_from_days(days);
        Date { year, month, day }
    }

    /// Days from 1970-01-01 to this date (negative before it).
    #[must_use]
    pub fn days(self) -> i64 {
        days_from_civil(self.year, self.month, self.day)
    }

    /// The year.
    #[must_use]
    pub fn year(self) -> i64 {
        self.year
    }

    /// The month, 1-12.
    #[must_use]
    pub fn month(self) -> u32 {
        self.month
    }

    /// The day of the month, 1-31.
    #[must_use]
    pub fn day(self) -> u32 {
        self.day
    }
}

/// `YYYY-MM-DD`, what [`Date::parse`] reads (for the years 0 to 9999; others are
/// written with more digits or a sign and do not read back).
impl fmt::Display for Date {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:04}-{:02}-{:02}", self.year, self.month, self.day)
    }
}

impl FromStr for Date {
    type Err = DateError;

    fn from_str(text: &str) -> Result<Date, DateError> {
        Date::parse(text)
    }
}

/// `SOURCE_DATE_EPOCH` is set, but not to seconds since 1970.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EpochError {
    /// The value as set (lossily, if it was not Unicode).
    pub value: String,
}

impl fmt::Display for EpochError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{SOURCE_DATE_EPOCH}={:?} is not a whole number of seconds since \
             1970-01-01T00:00:00Z (unset it to use the clock)",
            self.value
        )
    }
}

impl std::error::Error for EpochError {}

/// A UTC instant to the second: a date and a time of day.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Timestamp {
    date: Date,
    /// 0..86 400.
    second_of_day: u32,
}

impl Timestamp {
    /// The instant `seconds` after 1970-01-01T00:00:00Z (before it if negative).
    #[must_use]
    pub fn from_unix(seconds: i64) -> Timestamp {
        Timestamp {
            date: Date::from_days(seconds.div_euclid(SECONDS_PER_DAY)),
            // 0..86 400 by construction.
            second_of_day: seconds.rem_euclid(SECONDS_PER_DAY) as u32,
        }
    }

    /// Seconds since 1970-01-01T00:00:00Z (saturating at the ends of `i64`).
    #[must_use]
    pub fn unix(self) -> i64 {
        let seconds = i128::from(self.date.days()) * i128::from(SECONDS_PER_DAY)
            + i128::from(self.second_of_day);
        i64::try_from(seconds).unwrap_or(if seconds < 0 { i64::MIN } else { i64::MAX })
    }

    /// Now: `SOURCE_DATE_EPOCH` if it is set, else the clock ([`Timestamp::clock`]).
    ///
    /// # Errors
    /// `SOURCE_DATE_EPOCH` set to anything but an integer (the value is trimmed;
    /// `date +%s` is what it is made with): a reproducible output asked for and not
    /// made is an error, not the clock's time in its place.
    pub fn now() -> Result<Timestamp, EpochError> {
        Timestamp::now_given(std::env::var_os(SOURCE_DATE_EPOCH))
    }

    /// [`Timestamp::now`] with `SOURCE_DATE_EPOCH`'s value given.
    fn now_given(epoch: Option<std::ffi::OsString>) -> Result<Timestamp, EpochError> {
        match epoch {
            None => Ok(Timestamp::clock()),
            Some(value) => {
                let text = value.to_string_lossy();
                text.trim()
                    .parse::<i64>()
                    .map(Timestamp::from_unix)
                    .map_err(|_| EpochError {
                        value: text.into_owned(),
                    })
            }
        }
    }

    /// The system clock, whatever `SOURCE_DATE_EPOCH` says: when something happened.
    #[must_use]
    pub fn clock() -> Timestamp {
        let now = std::time::SystemTime::now();
        let seconds = match now.duration_since(std::time::UNIX_EPOCH) {
            Ok(after) => i64::try_from(after.as_secs()).unwrap_or(i64::MAX),
            Err(before) => i64::try_from(before.duration().as_secs()).map_or(i64::MIN, |s| -s),
        };
        Timestamp::from_unix(seconds)
    }

    /// The date.
    #[must_use]
    pub fn date(self) -> Date {
        self.date
    }

    /// The hour, 0-23.
    #[must_use]
    pub fn hour(self) -> u32 {
        self.second_of_day / 3600
    }

    /// The minute, 0-59.
    #[must_use]
    pub fn minute(self) -> u32 {
        self.second_of_day / 60 % 60
    }

    /// The second, 0-59.
    #[must_use]
    pub fn second(self) -> u32 {
        self.second_of_day % 60
    }
}

/// RFC 3339 in UTC, `YYYY-MM-DDTHH:MM:SSZ` (for the years 0 to 9999, which RFC 3339
/// covers).
impl fmt::Display for Timestamp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}T{:02}:{:02}:{:02}Z",
            self.date,
            self.hour(),
            self.minute(),
            self.second()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn date(y: i64, m: u32, d: u32) -> Date {
        Date::new(y, m, d).unwrap()
    }

    /// Known instants: the epoch, a leap day (2000-02-29T00:00:00Z is 951 782 400 s,
    /// day 11 016), 1 700 000 000 s, 2^31 s, the last second before the epoch.
    #[test]
    fn timestamps_match_known_instants() {
        let at = |s: i64| Timestamp::from_unix(s).to_string();
        assert_eq!(at(0), "1970-01-01T00:00:00Z");
        assert_eq!(at(951_782_400), "2000-02-29T00:00:00Z");
        assert_eq!(at(951_782_400 + 86_400), "2000-03-01T00:00:00Z");
        assert_eq!(at(1_700_000_000), "2023-11-14T22:13:20Z");
        assert_eq!(at(2_147_483_648), "2038-01-19T03:14:08Z");
        assert_eq!(at(20_784 * 86_400 + 86_399), "2026-11-27T23:59:59Z");
        assert_eq!(at(-1), "1969-12-31T23:59:59Z");
        let t = Timestamp::from_unix(1_700_000_000);
        assert_eq!((t.hour(), t.minute(), t.second()), (22, 13, 20));
        assert_eq!(t.date(), date(2023, 11, 14));
        assert_eq!(t.unix(), 1_700_000_000);
        assert_eq!(Timestamp::from_unix(-1).unix(), -1);
    }

    #[test]
    fn day_numbers_count_from_the_epoch() {
        assert_eq!(Date::EPOCH.days(), 0);
        assert_eq!(date(2000, 2, 29).days(), 11_016);
        assert_eq!(date(2026, 11, 27).days(), 20_784);
        assert_eq!(date(1969, 12, 31).days(), -1);
        // 0000-03-01 is the start of Hinnant's era 0.
        assert_eq!(date(0, 3, 1).days(), -719_468);
        assert_eq!(Date::from_days(-719_468), date(0, 3, 1));
        assert_eq!(
            Date::from_days(-719_469),
            date(0, 2, 29),
            "year 0 is a leap year"
        );
    }

    /// Every fourth year, except the centuries, except every fourth century.
    #[test]
    fn leap_years_are_gregorian() {
        assert!(is_leap_year(2024) && is_leap_year(2000) && is_leap_year(1600));
        assert!(!is_leap_year(2023) && !is_leap_year(1900) && !is_leap_year(2100));
        assert_eq!(days_in_month(2000, 2), Some(29));
        assert_eq!(days_in_month(1900, 2), Some(28));
        assert_eq!(days_in_month(2026, 4), Some(30));
        assert_eq!(days_in_month(2026, 13), None);
        // 1900 has no 29 February, so 1 March follows 28 February.
        assert_eq!(date(1900, 2, 28).days() + 1, date(1900, 3, 1).days());
        assert_eq!(date(2000, 2, 28).days() + 2, date(2000, 3, 1).days());
        // A year is 365 days, a leap year 366.
        assert_eq!(date(1901, 1, 1).days() - date(1900, 1, 1).days(), 365);
        assert_eq!(date(2001, 1, 1).days() - date(2000, 1, 1).days(), 366);
        // 400 Gregorian years are 146 097 days.
        assert_eq!(date(2400, 1, 1).days() - date(2000, 1, 1).days(), 146_097);
    }

    #[test]
    fn dates_read_strictly_and_say_what_is_wrong() {
        assert_eq!(Date::parse("2024-02-29"), Ok(date(2024, 2, 29)));
        assert_eq!("1999-01-31".parse::<Date>(), Ok(date(1999, 1, 31)));
        assert_eq!(
            Date::parse("2023-02-29"),
            Err(DateError::Day {
                year: 2023,
                month: 2,
                day: 29
            })
        );
        assert_eq!(
            Date::parse("2026-02-31").unwrap_err().to_string(),
            "2026-02 has no day 31 (it has 28)"
        );
        assert_eq!(
            Date::parse("2026-04-00").unwrap_err().to_string(),
            "2026-04 has no day 0 (it has 30)"
        );
        assert_eq!(
            Date::parse("2024-13-01"),
            Err(DateError::Month { month: 13 })
        );
        assert_eq!(
            Date::parse("2024-00-01").unwrap_err().to_string(),
            "month 0 is not 1 to 12"
        );
        for bad in [
            "",
            "24-04-01",
            "2024/04/01",
            "2024-0a-01",
            "2026-1-27",
            "20261127",
            "2026-11-27x",
            " 2026-11-27",
            "+202-11-27",
            "2026-11-2７",
        ] {
            assert_eq!(Date::parse(bad), Err(DateError::Shape), "{bad:?}");
        }
        assert_eq!(
            DateError::Shape.to_string(),
            "not four digits, '-', two digits, '-', two digits"
        );
    }

    #[test]
    fn a_caller_may_take_only_some_years() {
        let d = date(1999, 12, 31);
        assert_eq!(
            d.within_years(2000..=2999),
            Err(DateError::Year {
                year: 1999,
                first: 2000,
                last: 2999
            })
        );
        assert_eq!(
            d.within_years(2000..=2999).unwrap_err().to_string(),
            "year 1999 is not 2000 to 2999"
        );
        assert_eq!(
            date(2000, 1, 1).within_years(2000..=2999),
            Ok(date(2000, 1, 1))
        );
    }

    #[test]
    fn the_pendants_number_is_the_same_date() {
        assert_eq!(Date::from_yyyymmdd(20_240_229), Ok(date(2024, 2, 29)));
        assert_eq!(date(2026, 11, 27).yyyymmdd(), Some(20_261_127));
        assert_eq!(date(10_000, 1, 1).yyyymmdd(), None);
        assert_eq!(date(-1, 1, 1).yyyymmdd(), None);
        assert!(Date::from_yyyymmdd(20_230_229).is_err());
        assert!(Date::from_yyyymmdd(20_261_301).is_err());
    }

    #[test]
    fn dates_are_written_as_they_are_read() {
        assert_eq!(date(2026, 1, 2).to_string(), "2026-01-02");
        assert_eq!(date(33, 12, 25).to_string(), "0033-12-25");
        assert!(date(2026, 1, 2) < date(2026, 1, 10));
        assert!(date(1999, 12, 31) < date(2000, 1, 1));
    }

    /// `SOURCE_DATE_EPOCH` fixes now; set but not a number, it is an error.
    #[test]
    fn source_date_epoch_fixes_now_or_is_refused() {
        let given = |v: &str| Timestamp::now_given(Some(v.into()));
        assert_eq!(given("1700000000"), Ok(Timestamp::from_unix(1_700_000_000)));
        assert_eq!(given(" 0\n"), Ok(Timestamp::from_unix(0)));
        assert_eq!(given("-86400"), Ok(Timestamp::from_unix(-86_400)));
        for bad in ["", "soon", "1.5", "1e9", "99999999999999999999"] {
            let e = given(bad).unwrap_err();
            assert_eq!(e.value, bad);
            assert!(e.to_string().starts_with("SOURCE_DATE_EPOCH=\""), "{e}");
        }
        // Unset: the clock, which is after this test was written.
        let now = Timestamp::now_given(None).unwrap();
        assert!(now.date() >= date(2026, 1, 1), "{now}");
    }

    proptest! {
        /// Every day number is one date and back, and the next day is the next date.
        #[test]
        fn days_and_dates_round_trip(days in any::<i64>()) {
            let d = Date::from_days(days);
            prop_assert_eq!(d.days(), days);
            prop_assert!(Date::new(d.year(), d.month(), d.day()).is_ok());
            if days < i64::MAX {
                prop_assert!(Date::from_days(days + 1) > d);
            }
        }

        /// Every written date of the years 0 to 9999 reads back as itself.
        #[test]
        fn written_dates_read_back(days in -719_528i64..2_932_897) {
            let d = Date::from_days(days);
            prop_assert_eq!(Date::parse(&d.to_string()), Ok(d));
            prop_assert_eq!(d.yyyymmdd().map(Date::from_yyyymmdd), Some(Ok(d)));
        }

        /// Seconds to a timestamp and back.
        #[test]
        fn timestamps_round_trip(seconds in any::<i64>()) {
            let t = Timestamp::from_unix(seconds);
            prop_assert_eq!(t.unix(), seconds);
            prop_assert_eq!(
                i128::from(seconds) - i128::from(t.date().days()) * 86_400,
                i128::from(t.hour() * 3600 + t.minute() * 60 + t.second())
            );
        }
    }
}
