#!/usr/bin/env python3
"""Lists likely store-forwarding stalls in a binary, hottest first when given a perf profile.

A load that overlaps an earlier store to the same stack or object slot but is not contained in it
(a 1-byte flag stored, then the 8 bytes around it loaded; two 4-byte floats stored, then one 8-byte
load) cannot take its value from the store buffer and waits for the stores to commit: ~12 cycles.
GCC 12 makes that sequence when an out-of-line function returns a std::optional<float>, an
optional<Color> or a struct of a few floats in registers; docs/performance.md ("Small results not
returned through the stack") lists those fixed. Straight-line code only (a label or a jump between
store and load ends the search), so a loop's store and the next iteration's load are not reported.

  scripts/store-forwarding-scan.py build/rtpro                  # every candidate, by function
  scripts/store-forwarding-scan.py build/rtpro perf.data        # with the samples on each load

With a profile (perf record on the same binary), each candidate shows the share of its function's
samples on the load and the instruction after it (where a stalled load's samples land), and the
function's share of the whole profile; candidates are sorted by the product.
"""
import collections
import re
import signal
import subprocess
import sys

WINDOW = 8  # instructions searched back from a load for the store it overlaps

MEMORY = re.compile(r'^(-?0x[0-9a-f]+)?\((%r[a-z0-9]+)\)$')
SIZES = {
    'movb': 1, 'movw': 2, 'movl': 4, 'movss': 4, 'vmovss': 4, 'movd': 4, 'vmovd': 4,
    'movq': 8, 'vmovq': 8, 'movlps': 8, 'vmovlps': 8, 'movsd': 8, 'vmovsd': 8,
}
WIDE = {'movups', 'movaps', 'movdqu', 'movdqa', 'vmovups', 'vmovaps', 'vmovdqu', 'vmovdqa'}


def register_size(register):
    if re.fullmatch(r'%(r\d+b|[a-d]l|[sd]il|[sb]pl)', register):
        return 1
    if re.fullmatch(r'%(r\d+w|[a-d]x|[sd]i|[sb]p)', register):
        return 2
    if re.fullmatch(r'%(r\d+d|e[a-z]+)', register):
        return 4
    if re.fullmatch(r'%r[a-z0-9]+', register):
        return 8
    return None


def access(op, operands):
    """('store' | 'load', base register, offset, bytes) for a plain move to or from memory."""
    if len(operands) != 2:
        return None
    source, destination = operands
    if op in WIDE:
        size = 32 if '%ymm' in source + destination else 16
    elif op in SIZES:
        size = SIZES[op]
    elif op == 'mov':
        register = source if source.startswith('%') else destination
        size = register_size(register) if register.startswith('%') else None
    else:
        return None
    if size is None:
        return None
    for kind, operand in (('store', destination), ('load', source)):
        match = MEMORY.match(operand)
        if match:
            return kind, match.group(2), int(match.group(1) or '0', 16), size
    return None


def candidates(binary):
    listing = subprocess.run(['objdump', '-d', '--no-show-raw-insn', '-C', binary],
                             capture_output=True, text=True, check=True).stdout
    found, starts = collections.defaultdict(list), {}
    function, recent = None, collections.deque(maxlen=WINDOW)  # the last instructions' stores, or None
    for line in listing.splitlines():
        header = re.match(r'^([0-9a-f]+) <(.*)>:$', line)
        if header:
            function = header.group(2)
            starts.setdefault(short_name(function), int(header.group(1), 16))
            recent.clear()
            continue
        match = re.match(r'^\s+([0-9a-f]+):\s+(\S+)\s*(.*)$', line)
        if not match or function is None:
            continue
        address, op, text = match.groups()
        text = text.split('#')[0].strip()
        if op.startswith('j') or op in ('call', 'ret'):
            recent.clear()  # straight-line code only
            continue
        operands = [part.strip() for part in re.split(r',(?![^()]*\))', text)] if text else []
        move = access(op, operands)
        if move and move[0] == 'load':
            _, base, offset, size = move
            for store in reversed(recent):
                if store is None or store[1] != base:
                    continue
                _, _, store_offset, store_size, store_text = store
                overlaps = store_offset < offset + size and offset < store_offset + store_size
                contained = store_offset <= offset and offset + size <= store_offset + store_size
                if overlaps and not contained:
                    found[function].append((int(address, 16), f'{store_text}  ->  {op} {text}'))
                    break
        recent.append(move + (f'{op} {text}',) if move and move[0] == 'store' else None)
    return found, starts


def short_name(function):
    """A demangled name as perf prints it: without its parameters and clone suffix."""
    name = function.split(' [clone')[0]
    depth, cut = 0, len(name)
    for i, c in enumerate(name):
        if c == '(' and not name.startswith('(anonymous namespace)', i):
            if depth == 0:
                cut = i
                break
        depth += c == '<'
        depth -= c == '>'
    return name[:cut]


def profile(perf_data, binary, starts):
    """Samples per binary address and per function, from `perf script` (the binary's load address
    found from the first sample in a function the disassembly names)."""
    script = subprocess.run(['perf', 'script', '-i', perf_data, '-F', 'ip,sym,symoff,dso'],
                            capture_output=True, text=True).stdout
    at, per_function, total, base = collections.Counter(), collections.Counter(), 0, None
    for line in script.splitlines():
        match = re.match(r'^\s*([0-9a-f]+) (.*)\+0x([0-9a-f]+) \((.*)\)$', line)
        if not match:
            continue
        total += 1
        ip, symbol, offset, dso = int(match.group(1), 16), match.group(2), int(match.group(3), 16), match.group(4)
        if dso.rsplit('/', 1)[-1] != binary.rsplit('/', 1)[-1]:
            continue
        if base is None and symbol in starts:
            base = ip - offset - starts[symbol]
        per_function[symbol] += 1
        if base is not None:
            at[ip - base] += 1
    return at, per_function, max(total, 1)


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    binary = sys.argv[1]
    found, starts = candidates(binary)
    if len(sys.argv) == 2:
        for function, sites in sorted(found.items()):
            print(f'{len(sites):3} {function}')
            for address, text in sites:
                print(f'      {address:x}  {text}')
        return
    at, per_function, total = profile(sys.argv[2], binary, starts)
    rows = []
    for function, sites in found.items():
        samples = per_function.get(short_name(function), 0)
        if not samples:
            continue
        for address, text in sites:
            # The load's own samples and those of the next few bytes (the instruction after it).
            on_load = sum(at.get(address + k, 0) for k in range(0, 12))
            if on_load == 0:
                continue
            rows.append((on_load / total, on_load / samples, samples / total, function, address, text))
    for of_total, of_function, function_share, function, address, text in sorted(rows, reverse=True)[:40]:
        print(f'{100 * of_total:5.2f}% of all  ({100 * of_function:4.1f}% of a function at {100 * function_share:4.1f}%)'
              f'  {function[:90]}\n        {address:x}  {text}')


if __name__ == '__main__':
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # quiet when piped into head
    main()
