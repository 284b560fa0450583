//! Opaque handles: a registry of live objects keyed by ids that are never reused.
//!
//! A handle the caller holds is not an address: it is an id (a nonzero multiple of
//! [`STRIDE`], issued in increasing order) that the registry maps to the object and its kind.
//! Nothing the caller passes as a handle is ever dereferenced, so every misuse is detected
//! rather than undefined:
//!
//! - a handle of another kind (an `OceanSpectrum *` cast to `OceanLighting *`) is found with
//!   its real kind and refused;
//! - a destroyed handle is no longer in the registry, and its id is never issued again, so it
//!   cannot alias a newer object (no ABA);
//! - a second destroy, or a destroy through another kind's function, finds nothing to free and
//!   only sets the last-error message;
//! - a pointer the library never returned (zeroed memory, a stack address, a freed pointer) is
//!   not an id in the registry.
//!
//! Why a registry and not a tagged header in the object: a header must be read through the
//! caller's pointer, which is itself undefined behaviour for a freed, foreign or wild pointer
//! (and a poisoned header must be kept allocated for ever to stay readable). The registry reads
//! only its own memory.
//!
//! Each call takes a shared lock for one map lookup and clones the object's `Arc`, so an object
//! stays alive until every call that borrowed it returns: destroying a handle while another
//! thread is inside a call on it frees it when that call ends, never under it. `ocean bench
//! ffi` measures the cost per call.

use core::any::Any;
use std::collections::{BTreeMap, VecDeque};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::{Arc, PoisonError, RwLock, RwLockReadGuard, RwLockWriteGuard};

use crate::boundary::pointer::check_ptr;
use crate::status::{Error, OceanStatus, set_last_error};

/// A type the C ABI hands out as an opaque handle.
pub(crate) trait Handle: Any + Send + Sync {
    /// The C type name, for messages.
    const NAME: &'static str;
}

/// Declares handle types, each named after itself: every module that hands out a handle
/// declares its own, so that this module knows none of them.
macro_rules! handles {
    ($($ty:ident),* $(,)?) => {
        $(impl $crate::boundary::handle::Handle for $ty {
            const NAME: &'static str = stringify!($ty);
        })*
    };
}
pub(crate) use handles;

/// Distance between consecutive ids: handles look like aligned pointers to a C debugger.
const STRIDE: usize = 16;

/// The first id / STRIDE: small integers a caller might pass by mistake (1, 16, 0x10 as a
/// sentinel) are never ids.
const FIRST: usize = 0x1_0000;

/// How many destroyed handles keep their kind for messages ("a destroyed OceanWtbScene"); older
/// ones are still recognised as destroyed, without the kind.
const REMEMBERED_DESTROYED: usize = 1024;

struct Entry {
    kind: &'static str,
    object: Arc<dyn Any + Send + Sync>,
}

struct Registry {
    live: BTreeMap<usize, Entry>,
    /// The next id / STRIDE to issue; ids below it were issued once.
    next: usize,
    destroyed: VecDeque<(usize, &'static str)>,
}

static REGISTRY: RwLock<Registry> = RwLock::new(Registry {
    live: BTreeMap::new(),
    next: FIRST,
    destroyed: VecDeque::new(),
});

// A panic never happens while the lock is held (map operations only), but a poisoned lock
// must not turn every later call into a panic either.
fn read() -> RwLockReadGuard<'static, Registry> {
    REGISTRY.read().unwrap_or_else(PoisonError::into_inner)
}

fn write() -> RwLockWriteGuard<'static, Registry> {
    REGISTRY.write().unwrap_or_else(PoisonError::into_inner)
}

impl Registry {
    fn issue(&mut self, kind: &'static str, object: Arc<dyn Any + Send + Sync>) -> usize {
        loop {
            // 2^60 ids on 64-bit targets; where usize is 32 bits the count wraps after 2^28
            // creations, and an id still live is skipped.
            let id = self.next.wrapping_mul(STRIDE);
            self.next = (self.next.wrapping_add(1) & (usize::MAX / STRIDE)).max(FIRST);
            if id != 0 && !self.live.contains_key(&id) {
                self.live.insert(id, Entry { kind, object });
                return id;
            }
        }
    }

    /// Why `id`, which is not live, is not a `want` handle.
    fn dead(&self, id: usize, name: &str, want: &str) -> String {
        let remembered = self.destroyed.iter().rev().find(|(d, _)| *d == id);
        if let Some((_, kind)) = remembered {
            let wanted = if *kind == want {
                String::new()
            } else {
                format!(" (wanted an {want})")
            };
            format!("`{name}` ({id:#x}) is an {kind} handle that was destroyed{wanted}")
        } else if id.is_multiple_of(STRIDE) && (FIRST..self.next).contains(&(id / STRIDE)) {
            format!("`{name}` ({id:#x}) is a handle that was destroyed")
        } else {
            format!(
                "`{name}` ({id:#x}) is not an {want} handle: no function of this library \
                 returned it"
            )
        }
    }

    fn wrong_kind(name: &str, id: usize, kind: &str, want: &str) -> String {
        // Every kind's name starts with "Ocean", hence "an".
        format!("`{name}` ({id:#x}) is an {kind} handle, not an {want}")
    }
}

/// The object behind a handle of kind `T`.
///
/// Fails with `OCEAN_STATUS_NULL_POINTER` for NULL and `OCEAN_STATUS_INVALID_HANDLE` for a
/// handle of another kind, a destroyed one, or a value this library never returned. Never
/// reads through `p`.
pub(crate) fn borrow<T: Handle>(p: *const T, name: &str) -> Result<Arc<T>, Error> {
    if p.is_null() {
        return Err(Error::new(
            OceanStatus::NullPointer,
            format!("`{name}` is NULL"),
        ));
    }
    let id = p.addr();
    let registry = read();
    match registry.live.get(&id) {
        Some(entry) => Arc::clone(&entry.object).downcast::<T>().map_err(|_| {
            Error::new(
                OceanStatus::InvalidHandle,
                Registry::wrong_kind(name, id, entry.kind, T::NAME),
            )
        }),
        None => Err(Error::new(
            OceanStatus::InvalidHandle,
            registry.dead(id, name, T::NAME),
        )),
    }
}

/// Registers `value` and stores its new handle in `*out` (checked before anything is
/// registered).
///
/// # Safety
///
/// `out` must be NULL, misaligned, or writable.
pub(crate) unsafe fn write_handle<T: Handle>(out: *mut *mut T, value: T) -> Result<(), Error> {
    check_ptr(out.cast_const(), "out")?;
    let id = write().issue(T::NAME, Arc::new(value));
    // SAFETY: non-NULL and aligned (checked), writable (caller's guarantee).
    unsafe { out.write(core::ptr::without_provenance_mut(id)) };
    Ok(())
}

/// Unregisters and frees the object behind a handle of kind `T`; `function` is the destroy
/// function, for the message.
///
/// NULL is ignored. A handle of another kind, a destroyed one or an unknown value frees
/// nothing and sets the thread's last-error message (the destroy functions return no
/// status); a successful destroy leaves the message alone. The object is dropped once the
/// calls still using it on other threads return.
pub(crate) fn destroy<T: Handle>(p: *mut T, function: &str, name: &str) {
    if p.is_null() {
        return;
    }
    let id = p.addr();
    let outcome = {
        let mut registry = write();
        match registry.live.get(&id) {
            Some(entry) if entry.object.is::<T>() => {
                let entry = registry.live.remove(&id).expect("looked up above");
                if registry.destroyed.len() == REMEMBERED_DESTROYED {
                    registry.destroyed.pop_front();
                }
                registry.destroyed.push_back((id, entry.kind));
                Ok(entry.object)
            }
            Some(entry) => Err(Registry::wrong_kind(name, id, entry.kind, T::NAME)),
            None => Err(registry.dead(id, name, T::NAME)),
        }
    };
    match outcome {
        // Dropped outside the lock: a GPU object's drop may wait for its device.
        Ok(object) => {
            let _ = catch_unwind(AssertUnwindSafe(move || drop(object)));
        }
        Err(message) => set_last_error(Some(format!("{function}: {message}"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::status::last_error;

    struct Apple(u32);
    struct Orange;
    impl Handle for Apple {
        const NAME: &'static str = "OceanApple";
    }
    impl Handle for Orange {
        const NAME: &'static str = "OceanOrange";
    }

    fn create<T: Handle>(value: T) -> *mut T {
        let mut out = core::ptr::null_mut();
        // SAFETY: `out` is a local, writable.
        unsafe { write_handle(&mut out, value) }.unwrap();
        out
    }

    #[test]
    fn a_live_handle_of_its_kind_is_found() {
        let a = create(Apple(7));
        assert_eq!(borrow(a, "a").unwrap().0, 7);
        assert_eq!(a.addr() % STRIDE, 0);
        destroy(a, "destroy", "a");
    }

    #[test]
    fn null_is_a_null_pointer_and_a_null_destroy_is_silent() {
        let e = borrow::<Apple>(core::ptr::null(), "a").err().unwrap();
        assert_eq!(e.status, OceanStatus::NullPointer);
        set_last_error(Some("before".into()));
        destroy::<Apple>(core::ptr::null_mut(), "destroy", "a");
        assert_eq!(last_error(), "before");
    }

    #[test]
    fn another_kind_is_refused_with_both_names() {
        let o = create(Orange);
        let e = borrow(o.cast::<Apple>(), "apple").err().unwrap();
        assert_eq!(e.status, OceanStatus::InvalidHandle);
        assert!(
            e.message
                .contains("is an OceanOrange handle, not an OceanApple"),
            "{}",
            e.message
        );
        // Destroying through the wrong kind frees nothing: the orange is still there.
        destroy(o.cast::<Apple>(), "ocean_apple_destroy", "apple");
        assert!(last_error().starts_with("ocean_apple_destroy: `apple`"));
        assert!(borrow(o, "o").is_ok());
        destroy(o, "destroy", "o");
    }

    #[test]
    fn destroyed_handles_are_refused_and_a_second_destroy_only_sets_the_message() {
        let a = create(Apple(1));
        let kept = borrow(a, "a").unwrap();
        destroy(a, "ocean_apple_destroy", "a");
        // A call in flight keeps the object alive after the destroy.
        assert_eq!(kept.0, 1);
        let e = borrow(a, "a").err().unwrap();
        assert_eq!(e.status, OceanStatus::InvalidHandle);
        assert!(
            e.message.contains("OceanApple handle that was destroyed"),
            "{}",
            e.message
        );
        set_last_error(None);
        destroy(a, "ocean_apple_destroy", "a");
        assert!(last_error().contains("was destroyed"), "{}", last_error());
        // A new object never receives the destroyed id.
        let b = create(Apple(2));
        assert_ne!(a.addr(), b.addr());
        assert!(borrow(a, "a").is_err());
        destroy(b, "destroy", "b");
    }

    #[test]
    fn values_never_returned_are_refused_without_being_read() {
        let zeroed = [0u64; 8];
        for p in [
            zeroed.as_ptr().cast::<Apple>(),
            core::ptr::without_provenance(1),
            core::ptr::without_provenance(STRIDE),
            core::ptr::without_provenance(usize::MAX & !(STRIDE - 1)),
        ] {
            let e = borrow(p, "a").err().unwrap();
            assert_eq!(e.status, OceanStatus::InvalidHandle, "{p:p}");
            assert!(
                e.message
                    .contains("no function of this library returned it")
            );
        }
    }

    #[test]
    fn handles_are_shared_between_threads() {
        let a = create(Apple(3)).addr();
        let sum: u32 = std::thread::scope(|s| {
            let workers: Vec<_> = (0..8)
                .map(|_| {
                    s.spawn(move || {
                        let p = core::ptr::without_provenance::<Apple>(a);
                        (0..1000).map(|_| borrow(p, "a").unwrap().0).sum::<u32>()
                    })
                })
                .collect();
            workers.into_iter().map(|w| w.join().unwrap()).sum()
        });
        assert_eq!(sum, 8 * 1000 * 3);
        destroy(
            core::ptr::without_provenance_mut::<Apple>(a),
            "destroy",
            "a",
        );
    }
}
