/* Start-up of the bare-metal Cortex-M builds (golden program, panel demo,
 * `make cortexm`): a vector table, .data/.bss set-up, static constructors,
 * main, and nothing else. No heap set-up, no C library initialisation.
 *
 * The FPU (M4F, M7) is switched on, as a hard-float firmware must even for
 * integer-only code: GCC moves 64-bit integers through d registers
 * (vldr/vstr d8) at -Os when the FPU is there, and without CP10/CP11 access
 * those moves fault. core/ and display/ themselves must contain no FPU
 * instruction at all; `make cortexm` checks that per object.
 */
#include <stdint.h>

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
extern void (*__init_array_start[])(void), (*__init_array_end[])(void);

int main(int argc, char** argv);
/* board_semihost.cpp on the emulated boards; a stub in `make cortexm`. */
void board_exit(int code) __attribute__((noreturn));
void board_fault(void) __attribute__((noreturn));
void SysTick_Handler(void) __attribute__((weak));

void* __dso_handle = 0; /* normally from crtbegin.o; static destructors refer to it */

void Reset_Handler(void) {
#if defined(__ARM_FP)
  *(volatile uint32_t*)0xE000ED88u |= 0xFu << 20; /* CPACR: full access to CP10, CP11 */
  __asm__ volatile("dsb\n isb" ::: "memory");
#endif
  uint32_t *src = &_sidata, *dst = &_sdata;
  while (dst < &_edata) *dst++ = *src++;
  for (dst = &_sbss; dst < &_ebss;) *dst++ = 0;
  for (void (**f)(void) = __init_array_start; f < __init_array_end; ++f) (*f)();
  board_exit(main(0, 0));
}

static void Fault_Handler(void) { board_fault(); }

__attribute__((section(".isr_vector"), used)) void* const g_vectors[16] = {
    &_estack,              /* initial stack pointer: top of RAM */
    (void*)Reset_Handler,  /* reset */
    (void*)Fault_Handler,  /* NMI */
    (void*)Fault_Handler,  /* HardFault */
    (void*)Fault_Handler,  /* MemManage (v7-M) */
    (void*)Fault_Handler,  /* BusFault (v7-M) */
    (void*)Fault_Handler,  /* UsageFault (v7-M) */
    0, 0, 0, 0,
    (void*)Fault_Handler,  /* SVCall */
    (void*)Fault_Handler,  /* DebugMon */
    0,
    (void*)Fault_Handler,  /* PendSV */
    (void*)SysTick_Handler /* SysTick (weak: 0 when no board counts time) */
};
