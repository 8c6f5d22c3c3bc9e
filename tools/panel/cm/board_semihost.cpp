// Board of the bare-metal Cortex-M targets on qemu-system-arm's MPS2 boards:
// output and exit through Arm semihosting (`bkpt 0xAB`; qemu is started with
// -semihosting-config enable=on,target=native,chardev=... so it reaches
// stdout), and an instruction count from SysTick.
//
// Instruction counting: qemu models no DWT cycle counter (CYCCNT reads 0).
// Under `-icount shift=0` every instruction advances the virtual clock by
// exactly 1 ns, and SysTick (CPU clock source, 25 MHz on MPS2) counts that
// virtual clock, so ticks are proportional to retired instructions. The
// first call calibrates the ratio with a loop of known length instead of
// trusting the 25 MHz figure; the result is accurate to about one tick
// (~40 instructions). Without -icount the ticks follow host time and mean
// nothing, which is why panel.sh always passes -icount.
#include <stdint.h>

#include "tools/panel/board.h"

namespace {

// Semihosting operations (Arm "Semihosting for AArch32 and AArch64", v2).
constexpr int kSysWrite0 = 0x04;        // write a NUL-terminated string to the console
constexpr int kSysExitExtended = 0x20;  // exit with a reason and a status
constexpr uint32_t kAdpStoppedApplicationExit = 0x20026u;

int semihost(int op, const void* arg) {
  register int r0 __asm__("r0") = op;
  register const void* r1 __asm__("r1") = arg;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

// SysTick and the System Control Block (ARMv6-M / ARMv7-M).
volatile uint32_t& reg(uintptr_t a) { return *reinterpret_cast<volatile uint32_t*>(a); }
constexpr uintptr_t kSystCsr = 0xE000E010u, kSystRvr = 0xE000E014u, kSystCvr = 0xE000E018u;
constexpr uintptr_t kScbIcsr = 0xE000ED04u;
constexpr uint32_t kIcsrPendStSet = 1u << 26;
constexpr uint32_t kSysTickReload = 0x00FFFFFFu;  // 24-bit counter

volatile uint32_t g_systick_wraps = 0;
bool g_clock_started = false;
uint64_t g_cal_instructions = 1, g_cal_ticks = 1;

uint64_t systick_ticks() {
  uint32_t primask;
  __asm__ volatile("mrs %0, primask" : "=r"(primask));
  __asm__ volatile("cpsid i" ::: "memory");
  uint32_t val = reg(kSystCvr);
  uint64_t wraps = g_systick_wraps;
  if (reg(kScbIcsr) & kIcsrPendStSet) {  // wrapped, handler not run yet
    val = reg(kSystCvr);
    ++wraps;
  }
  if (!primask) __asm__ volatile("cpsie i" ::: "memory");
  return wraps * (static_cast<uint64_t>(kSysTickReload) + 1u) + (kSysTickReload - val);
}

// Exactly 2 * n + 1 instructions after the first (subs, bne per turn).
void known_loop(uint32_t n) {
  // GCC hands Thumb-1 (ARMv6-M) inline assembly over in "divided" syntax;
  // say unified explicitly (it switches back to unified after the block).
  __asm__ volatile(
      ".syntax unified\n"
      "1: subs %0, %0, #1\n"
      "   bne 1b\n"
      : "+l"(n)
      :
      : "cc", "memory");  // "memory": keep it between the two SysTick reads
}

void clock_start() {
  reg(kSystRvr) = kSysTickReload;
  reg(kSystCvr) = 0;
  reg(kSystCsr) = 7u;  // enable, interrupt on wrap, processor clock
  // The counter starts at 0 and reloads on the first tick, which is not a
  // wrap; count from after the reload.
  while (reg(kSystCvr) == 0) {}
  g_clock_started = true;
  constexpr uint32_t kTurns = 1000000;
  const uint64_t t0 = systick_ticks();
  known_loop(kTurns);
  const uint64_t t1 = systick_ticks();
  g_cal_instructions = 2u * static_cast<uint64_t>(kTurns);
  g_cal_ticks = t1 > t0 ? t1 - t0 : 1u;
}

}  // namespace

extern "C" void SysTick_Handler() { g_systick_wraps = g_systick_wraps + 1u; }

extern "C" __attribute__((noreturn)) void board_exit(int code) {
  static uint32_t block[2];
  block[0] = kAdpStoppedApplicationExit;
  block[1] = static_cast<uint32_t>(code);
  semihost(kSysExitExtended, block);
  for (;;) {}
}

extern "C" __attribute__((noreturn)) void board_fault() {
  semihost(kSysWrite0, "*** Cortex-M fault (HardFault/MemManage/BusFault/UsageFault, or an FPU instruction) ***\n");
  board_exit(99);
}

// A pure virtual call is a bug; the library version would drag in
// std::terminate and the C library's abort machinery.
extern "C" void __cxa_pure_virtual() { board_fault(); }

namespace golden {

void board_write(const char* s, size_t n) {
  char chunk[129];
  while (n > 0) {
    size_t k = n < sizeof chunk - 1 ? n : sizeof chunk - 1;
    for (size_t i = 0; i < k; ++i) chunk[i] = s[i];
    chunk[k] = 0;
    semihost(kSysWrite0, chunk);
    s += k;
    n -= k;
  }
}

uint64_t board_instructions() {
  if (!g_clock_started) clock_start();
  // ticks * (instructions per tick), rounded; 64-bit is plenty for minutes
  // of emulated time.
  return (systick_ticks() * g_cal_instructions + g_cal_ticks / 2) / g_cal_ticks;
}

const char* board_clock_name() {
  return "instructions from SysTick under qemu -icount shift=0 (calibrated, +-1 tick)";
}

}  // namespace golden
