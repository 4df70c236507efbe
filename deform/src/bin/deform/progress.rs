//! Progress on the terminal (indicatif): a spinner while a large mesh binds, a bar while a
//! frame sequence is posed. Never with `--quiet`.

use indicatif::{ProgressBar, ProgressStyle};
use std::time::Duration;

/// Run `f` under a spinner when it may take a while (large meshes, an interactive terminal,
/// not `--quiet`).
pub fn with_progress<T>(message: &str, vertices: usize, quiet: bool, f: impl FnOnce() -> T) -> T {
    let bar = (!quiet && vertices >= 20_000).then(|| {
        let b = ProgressBar::new_spinner();
        b.set_style(
            ProgressStyle::with_template("{spinner} {msg} {elapsed}")
                .unwrap_or_else(|_| ProgressStyle::default_spinner()),
        );
        b.set_message(message.to_string());
        b.enable_steady_tick(Duration::from_millis(100));
        b
    });
    let out = f();
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    out
}

/// A bar over `frames` frames being posed, when `show`.
pub fn frames(frames: usize, show: bool) -> Option<ProgressBar> {
    show.then(|| {
        let bar = ProgressBar::new(frames as u64);
        let style = ProgressStyle::with_template("posing frames {pos}/{len} {bar:30} {elapsed}");
        bar.set_style(style.unwrap_or_else(|_| ProgressStyle::default_bar()));
        bar
    })
}
