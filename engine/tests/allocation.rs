//! No heap allocation inside `Env::step` once the env is reset (issue 3): a counting global
//! allocator watches thousands of steps of a full match and of an Academy drill.

mod common;

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use touchline_engine::Action;

struct Counting;

// Per thread: the test harness's own threads allocate while the test runs.
thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    if COUNTING.with(Cell::get) {
        ALLOCATIONS.with(|a| a.set(a.get() + 1));
    }
}

// SAFETY: every call is forwarded unchanged to the system allocator; the wrapper only counts.
#[expect(unsafe_code, reason = "a global allocator must implement an unsafe trait")]
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        // SAFETY: same contract as the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn step_does_not_allocate() {
    for (name, builtin) in
        [("11_vs_11_easy_stochastic", true), ("academy_empty_goal_close", false), ("academy_corner", false)]
    {
        let mut env = if builtin { common::builtin_env(name, 1) } else { common::env(name, 1) };
        let mut policy = common::RandomPolicy::new(3);
        let mut actions = [Action::Idle; 1];
        for _ in 0..3000 {
            actions[0] = if builtin { Action::BuiltinAi } else { policy.action(env.action_set()) };
            COUNTING.with(|c| c.set(true));
            let out = env.step(&actions).unwrap();
            COUNTING.with(|c| c.set(false));
            if out.terminated || out.truncated {
                env.reset();
            }
        }
        assert_eq!(ALLOCATIONS.with(Cell::get), 0, "{name}: step allocated");
    }
}
