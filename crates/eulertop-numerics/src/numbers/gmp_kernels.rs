//! The GMP kernels for this processor.
//!
//! The bundled GMP (6.3, built by `gmp-mpfr-sys` as a "fat" library) carries the
//! assembly kernels of many x86-64 processors and picks them at its first call from
//! the processor's CPUID family (`mpn/x86_64/fat/fat.c`).  Its table ends at AMD
//! family 0x19 (Zen 3/4): on a later family (0x1A, Zen 5) it falls back to the
//! generic x86-64 kernels, which are 1.4–1.5× slower than the Zen kernels in the same
//! library (`mpn_addmul_1` on 32 limbs 14.5 against 10.3 ns, `mpn_mul_basecase` 20×20
//! 185 against 122 ns on this machine; reports/performance.md).  Those kernels are
//! more than a third of a high-precision audit.
//!
//! [`select`] makes GMP choose as its dispatch does for Zen (`CPUVEC_SETUP_zen`: the
//! fifteen `*_zen` kernels and the thresholds of `mpn/x86_64/zen/gmp-mparam.h`) on an
//! AMD processor of a family the table does not know, when the processor has the
//! instructions those kernels use (BMI2's `mulx`, ADX's `adcx`/`adox`).  Everywhere
//! else it leaves GMP's own choice.  The kernels compute the same limbs, so results
//! are bit-identical either way; only the speed differs.
//!
//! GMP's dispatch table (`struct cpuvec_t` of GMP 6.3's `gmp-impl.h`) is written
//! once, before any other thread uses GMP: call [`select`] at the start of `main`.  A
//! GMP other than 6.3 (by its version string) is left alone, as its table may differ.

/// What [`select`] did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kernels {
    /// GMP's own choice stands (a processor its table knows, or not AMD, or not x86-64).
    Gmp,
    /// The Zen kernels were installed for a later AMD family.
    Zen,
}

#[cfg(all(target_arch = "x86_64", target_os = "linux"))]
mod imp {
    use super::Kernels;

    /// GMP 6.3's `struct cpuvec_t`: 37 kernel pointers, then 5 thresholds.
    #[repr(C)]
    struct CpuVec {
        kernels: [usize; 37],
        thresholds: [isize; 5],
    }

    unsafe extern "C" {
        static __gmp_version: *const std::ffi::c_char;
        static mut __gmpn_cpuvec: CpuVec;
        fn __gmpn_cpuvec_init();
        fn __gmpn_addlsh1_n_zen();
        fn __gmpn_addmul_1_zen();
        fn __gmpn_com_zen();
        fn __gmpn_copyd_zen();
        fn __gmpn_copyi_zen();
        fn __gmpn_gcd_11_zen();
        fn __gmpn_lshift_zen();
        fn __gmpn_lshiftc_zen();
        fn __gmpn_mul_1_zen();
        fn __gmpn_mul_basecase_zen();
        fn __gmpn_mullo_basecase_zen();
        fn __gmpn_rshift_zen();
        fn __gmpn_sqr_basecase_zen();
        fn __gmpn_sublsh1_n_zen();
        fn __gmpn_submul_1_zen();
    }

    /// The CPUID vendor and family (with the extended family added, as `fat.c` does).
    fn vendor_family() -> ([u8; 12], u32) {
        use std::arch::x86_64::__cpuid;
        // SAFETY: CPUID leaves 0 and 1 exist on every x86-64 processor.  (`__cpuid` is
        // a safe function in current Rust and unsafe in earlier releases such as 1.91:
        // the block serves both.)
        #[allow(unused_unsafe)]
        let (l0, l1) = unsafe { (__cpuid(0), __cpuid(1)) };
        let mut vendor = [0u8; 12];
        vendor[0..4].copy_from_slice(&l0.ebx.to_le_bytes());
        vendor[4..8].copy_from_slice(&l0.edx.to_le_bytes());
        vendor[8..12].copy_from_slice(&l0.ecx.to_le_bytes());
        let base = (l1.eax >> 8) & 0xf;
        let family = if base == 0xf {
            base + ((l1.eax >> 20) & 0xff)
        } else {
            base
        };
        (vendor, family)
    }

    /// Is the linked GMP the 6.3 whose table layout this module writes?
    fn gmp_6_3() -> bool {
        // SAFETY: `__gmp_version` is GMP's constant, NUL-terminated version string.
        let v = unsafe { std::ffi::CStr::from_ptr(__gmp_version) };
        v.to_bytes().starts_with(b"6.3.")
    }

    pub(super) fn select() -> Kernels {
        if !gmp_6_3() {
            return Kernels::Gmp;
        }
        let (vendor, family) = vendor_family();
        let later_amd = &vendor == b"AuthenticAMD" && family > 0x19;
        if !later_amd
            || !std::arch::is_x86_feature_detected!("bmi2")
            || !std::arch::is_x86_feature_detected!("adx")
        {
            return Kernels::Gmp;
        }
        // the field indices of `struct cpuvec_t` (gmp-impl.h of GMP 6.3)
        let zen: [(usize, unsafe extern "C" fn()); 15] = [
            (1, __gmpn_addlsh1_n_zen),
            (3, __gmpn_addmul_1_zen),
            (8, __gmpn_com_zen),
            (9, __gmpn_copyd_zen),
            (10, __gmpn_copyi_zen),
            (13, __gmpn_gcd_11_zen),
            (14, __gmpn_lshift_zen),
            (15, __gmpn_lshiftc_zen),
            (25, __gmpn_mul_1_zen),
            (26, __gmpn_mul_basecase_zen),
            (27, __gmpn_mullo_basecase_zen),
            (32, __gmpn_rshift_zen),
            (33, __gmpn_sqr_basecase_zen),
            (35, __gmpn_sublsh1_n_zen),
            (36, __gmpn_submul_1_zen),
        ];
        // MUL_TOOM22, MUL_TOOM33, SQR_TOOM2, SQR_TOOM3, BMOD_1_TO_MOD_1 of
        // mpn/x86_64/zen/gmp-mparam.h
        let thresholds: [isize; 5] = [16, 107, 32, 114, 22];
        // SAFETY: GMP first fills its table by its own dispatch (after which it never
        // writes it again); the table is then overwritten, field by field, with kernels
        // of the same signatures that the processor can run, before any other thread
        // calls GMP (the caller's contract).
        unsafe {
            __gmpn_cpuvec_init();
            let table = &raw mut __gmpn_cpuvec;
            for (i, f) in zen {
                (*table).kernels[i] = f as usize;
            }
            (*table).thresholds = thresholds;
        }
        Kernels::Zen
    }
}

/// Makes GMP use the fastest kernels it carries for this processor where its own
/// dispatch falls back to generic ones (see the module documentation); returns what
/// it did.  Call it once, at the start of `main`, before any other thread runs.
///
/// ```
/// let k = eulertop_numerics::numbers::gmp_kernels::select();
/// // the results of GMP are the same either way
/// let x = rug::Float::with_val(8192, 3).sqrt();
/// let err = (x.clone() * &x - 3u32).abs();
/// assert!(err.is_zero() || err.get_exp().unwrap() < -8000);
/// # let _ = k;
/// ```
pub fn select() -> Kernels {
    #[cfg(all(target_arch = "x86_64", target_os = "linux"))]
    {
        imp::select()
    }
    #[cfg(not(all(target_arch = "x86_64", target_os = "linux")))]
    {
        Kernels::Gmp
    }
}
