//! The procedure task: turns sensor reports and button presses into the [`Screen`] to
//! show, and talks to the calibration store.
//!
//! PLACEHOLDER for the calibration procedure: it will run the state machine of
//! `zerocal-core` (stage 0/1/2, `step(&config, &mut state, event) -> Action`), whose
//! actions become screens and storage requests. Until then it shows the live reading,
//! NEXT toggles to an About page, and it counts power-ups in the store (exercising the
//! flash path at every boot). OK and BACK do nothing yet.

use embassy_futures::select::{select, Either};

use crate::channels::{BUTTON_PRESSES, SCREEN, SENSOR_REPORTS, STORAGE_REPLIES, STORAGE_REQUESTS};
use crate::screen::Screen;
use crate::tasks::buttons::Button;
use crate::tasks::sensor::SensorReport;
use crate::tasks::storage::{Record, RecordValue, StorageReply, StorageRequest};

/// The placeholder's pages.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Page {
    Live,
    About,
}

/// Runs forever.
#[embassy_executor::task]
pub async fn procedure_task() -> ! {
    SCREEN.signal(Screen::Starting);
    let boot_count = count_boot().await;
    defmt::info!("boot count: {}", boot_count);

    let mut page = Page::Live;
    let mut latest: Option<SensorReport> = None;
    loop {
        match select(SENSOR_REPORTS.wait(), BUTTON_PRESSES.receive()).await {
            Either::First(report) => latest = Some(report),
            Either::Second(Button::Next) => {
                page = match page {
                    Page::Live => Page::About,
                    Page::About => Page::Live,
                }
            }
            Either::Second(Button::Ok | Button::Back) => {}
        }
        SCREEN.signal(screen(page, latest, boot_count));
    }
}

/// The screen for the current page and the newest sensor report.
fn screen(page: Page, latest: Option<SensorReport>, boot_count: Option<u32>) -> Screen {
    let dropped_frames = match latest {
        Some(SensorReport::Reading { dropped_frames, .. }) => dropped_frames,
        _ => 0,
    };
    match (page, latest) {
        (Page::About, _) => Screen::About {
            boot_count,
            dropped_frames,
        },
        (Page::Live, None) => Screen::Starting,
        (Page::Live, Some(SensorReport::Fault(fault))) => Screen::SensorFault(fault),
        (
            Page::Live,
            Some(SensorReport::Reading {
                x_rad,
                y_rad,
                dropped_frames,
            }),
        ) => Screen::Live {
            x_deg: x_rad.to_degrees(),
            y_deg: y_rad.to_degrees(),
            dropped_frames,
        },
    }
}

/// Reads, increments and stores the boot count; `None` if the store fails.
async fn count_boot() -> Option<u32> {
    STORAGE_REQUESTS
        .send(StorageRequest::Fetch(Record::BootCount))
        .await;
    let previous = match STORAGE_REPLIES.receive().await {
        StorageReply::Fetched(Some(RecordValue::BootCount(count))) => count,
        StorageReply::Fetched(None) => 0,
        StorageReply::Fetched(Some(_)) | StorageReply::Stored | StorageReply::Failed => {
            return None
        }
    };
    let count = previous.saturating_add(1);
    STORAGE_REQUESTS
        .send(StorageRequest::Store(RecordValue::BootCount(count)))
        .await;
    match STORAGE_REPLIES.receive().await {
        StorageReply::Stored => Some(count),
        _ => None,
    }
}
