#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The portable binary keeps every instruction beyond baseline x86-64 (SSE2) inside the kernel
# namespaces that run only after CPUID said yes (ifs/detail/walk_kernels.h): no VEX or EVEX
# instruction (v-prefixed mnemonics, ymm/zmm/mask registers), no SSE3 to SSE4.2, BMI, LZCNT,
# MOVBE or POPCNT instruction anywhere else. The linker keeps one copy of each inline function or
# template instance (COMDAT); had an AVX2 translation unit shared one with baseline code, its copy
# could be the one kept, and the baseline path would die with SIGILL on an older CPU.
# Also checks that the kernels are there at all (ymm code in kernel_avx2, zmm in kernel_avx512),
# so that a renamed namespace cannot make this test pass by hiding everything.
#   kernel_isolation_test.sh BINARY
set -euo pipefail
binary=$1
command -v objdump >/dev/null || { echo "SKIP: no objdump"; exit 77; }
objdump -d -C --no-show-raw-insn "$binary" | awk '
  function flag(kind) {
    if (++bad <= 40) printf "FAIL: %s instruction outside the kernels in %s: %s\n", kind, symbol, insn
  }
  /^[0-9a-f]+ <.*>:$/ {
    symbol = $0
    sub(/^[0-9a-f]+ </, "", symbol)
    sub(/>:$/, "", symbol)
    # (after a return type, when the demangler shows one)
    avx2 = symbol ~ /(^| )ifsfx::detail::kernel_avx2::/
    avx512 = symbol ~ /(^| )ifsfx::detail::kernel_avx512::/
    next
  }
  /^ +[0-9a-f]+:\t/ {
    insn = $0
    sub(/^ +[0-9a-f]+:\t/, "", insn)
    mnemonic = insn
    sub(/[ \t].*/, "", mnemonic)
    if (avx2 && insn ~ /%ymm/) ymm++
    if (avx512 && insn ~ /%zmm/) zmm++
    if (avx2 || avx512) next
    if (mnemonic ~ /^v/ || insn ~ /%[yz]mm|%k[0-7]/) flag("VEX/EVEX")
    # tzcnt is F3 0F BC, which a CPU without BMI1 runs as bsf: GCC emits it for baseline x86-64
    # where the result for 0 does not matter (std::countr_zero of a nonzero word), so it is safe.
    else if (mnemonic ~ /^(andn|bextr|blsi|blsmsk|blsr|bzhi|lzcnt|mulx|pdep|pext|rorx|sarx|shlx|shrx|movbe|popcnt|crc32[bwlq]?|adcx|adox)[wlq]?$/)
      flag("BMI/LZCNT/MOVBE/POPCNT")
    else if (mnemonic ~ /^(addsubp[sd]|haddp[sd]|hsubp[sd]|lddqu|movddup|movshdup|movsldup|pabs[bwd]|palignr|phadd(w|d|sw)|phsub(w|d|sw)|pmaddubsw|pmulhrsw|pshufb|psign[bwd]|blendp[sd]|blendvp[sd]|dpp[sd]|extractps|insertps|movntdqa|mpsadbw|packusdw|pblendvb|pblendw|pcmpeqq|pcmpgtq|pcmp[ei]str[im]|pextr[bdq]|phminposuw|pinsr[bdq]|pmaxs[bd]|pmaxu[wd]|pmins[bd]|pminu[wd]|pmovsx(bw|bd|bq|wd|wq|dq)|pmovzx(bw|bd|bq|wd|wq|dq)|pmuldq|pmulld|ptest|round[ps][sd])$/)
      flag("SSE3..SSE4.2")
  }
  END {
    if (ymm == 0) { print "FAIL: no ymm instruction in ifsfx::detail::kernel_avx2 (kernels missing?)"; bad++ }
    if (zmm == 0) { print "FAIL: no zmm instruction in ifsfx::detail::kernel_avx512 (kernels missing?)"; bad++ }
    if (bad > 0) { printf "FAIL: %d instruction(s) beyond baseline x86-64 outside the kernels\n", bad; exit 1 }
    printf "PASS: %d ymm instructions in kernel_avx2, %d zmm in kernel_avx512, none beyond SSE2 elsewhere\n", ymm, zmm
  }'
