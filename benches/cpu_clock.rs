//! CPU-time clocks for the benchmarks and `diagnostics/world_bench.rs`
//! (included with `#[path]`): on a loaded machine CPU time is steadier than
//! wall time. Hand-written because it is one libc call and the crates that
//! wrap it (`cpu-time`, `libc`) would be dependencies for two benchmarks.

#[cfg(target_os = "linux")]
mod imp {
    #[repr(C)]
    struct Timespec {
        tv_sec: i64,
        tv_nsec: i64,
    }
    extern "C" {
        fn clock_gettime(clock: i32, ts: *mut Timespec) -> i32;
    }

    pub fn now_ns(clock: i32) -> Option<u128> {
        let mut ts = Timespec {
            tv_sec: 0,
            tv_nsec: 0,
        };
        // SAFETY: `ts` is a valid, writable timespec for the call.
        #[allow(unsafe_code)]
        let rc = unsafe { clock_gettime(clock, &mut ts) };
        (rc == 0).then(|| ts.tv_sec as u128 * 1_000_000_000 + ts.tv_nsec as u128)
    }
}

#[cfg(not(target_os = "linux"))]
mod imp {
    pub fn now_ns(_clock: i32) -> Option<u128> {
        None
    }
}

/// This process's CPU time in ns, if the clock is available.
#[allow(dead_code)]
pub fn process_ns() -> Option<u128> {
    imp::now_ns(2) // CLOCK_PROCESS_CPUTIME_ID
}

/// This thread's CPU time in ns, if the clock is available.
#[allow(dead_code)]
pub fn thread_ns() -> Option<u128> {
    imp::now_ns(3) // CLOCK_THREAD_CPUTIME_ID
}
