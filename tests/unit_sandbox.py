#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Runs a command under the system call filter a systemd unit file asks for,
as systemd 252 builds it, without a running systemd: the unit's
SystemCallFilter= lines (an allow-list: the first line's sets plus @default,
then each ~ line's sets taken out, the sets expanded by
`systemd-analyze syscall-filter`), SystemCallErrorNumber= for what is
refused, MemoryDenyWriteExecute= (a second filter, as systemd's: mmap
asking for write and execute at once, and mprotect or pkey_mprotect asking
for execute, refused with EPERM) and NoNewPrivileges=. Through libseccomp's
shared library (Debian libseccomp2, on every systemd system); no headers
needed. Used by test_service.sh to run seamwalk as the unit would, so the
unit's hardening is tested against what llvmpipe's JIT does, not only read.
  unit_sandbox.py UNIT-FILE COMMAND [ARG...]"""
import ctypes, errno, os, subprocess, sys

unit, argv = sys.argv[1], sys.argv[2:]

# The unit's [Service] settings this sandbox applies, in file order.
filters, errno_name, mdwe, nnp = [], 'EPERM', False, False
for line in open(unit):
    key, _, value = line.strip().partition('=')
    if key == 'SystemCallFilter':
        filters.append(value.split())
    elif key == 'SystemCallErrorNumber':
        errno_name = value.strip()
    elif key == 'MemoryDenyWriteExecute':
        mdwe = value.strip() in ('yes', 'true', '1', 'on')
    elif key == 'NoNewPrivileges':
        nnp = value.strip() in ('yes', 'true', '1', 'on')

# systemd-analyze syscall-filter: "@set" lines, then its members indented
# (comments start with #), sets separated by a blank line.
groups, current = {}, None
for line in subprocess.run(['systemd-analyze', 'syscall-filter'], check=True,
                           capture_output=True, text=True).stdout.splitlines():
    if line.startswith('@'):
        current = groups.setdefault(line.strip(), [])
    elif line.strip() and not line.strip().startswith('#') and current is not None:
        current.append(line.strip())
    elif not line.strip():
        current = None


def expand(name, seen=()):
    if not name.startswith('@'):
        return {name}
    if name not in groups:
        sys.exit(f'unit_sandbox: {unit}: unknown system call set {name}')
    out = set()
    for member in groups[name]:
        if member not in seen:
            out |= expand(member, seen + (name,))
    return out


allowed = None
for entries in filters:
    deny = entries[0].startswith('~')
    names = set()
    for e in entries:
        names |= expand(e.lstrip('~'))
    if allowed is None:
        if deny:
            sys.exit('unit_sandbox: a deny-list filter (first line with ~) is not what the unit has')
        allowed = expand('@default')
    allowed = allowed - names if deny else allowed | names

seccomp = ctypes.CDLL('libseccomp.so.2', use_errno=True)
seccomp.seccomp_init.restype = ctypes.c_void_p
seccomp.seccomp_init.argtypes = [ctypes.c_uint32]
seccomp.seccomp_syscall_resolve_name.argtypes = [ctypes.c_char_p]
seccomp.seccomp_rule_add_array.argtypes = [ctypes.c_void_p, ctypes.c_uint32, ctypes.c_int,
                                           ctypes.c_uint, ctypes.c_void_p]
seccomp.seccomp_load.argtypes = [ctypes.c_void_p]
SCMP_ACT_ALLOW = 0x7fff0000
SCMP_CMP_MASKED_EQ = 7
PROT_WRITE, PROT_EXEC = 0x2, 0x4


def act_errno(code):
    return 0x00050000 | (code & 0xffff)


class ArgCmp(ctypes.Structure):
    _fields_ = [('arg', ctypes.c_uint), ('op', ctypes.c_int),
                ('datum_a', ctypes.c_uint64), ('datum_b', ctypes.c_uint64)]


def syscall_nr(name):
    nr = seccomp.seccomp_syscall_resolve_name(name.encode())
    return nr if nr >= 0 else None   # another architecture's call: nothing to add


def load(ctx):
    if seccomp.seccomp_load(ctx) != 0:
        sys.exit('unit_sandbox: seccomp_load failed')


refuse = act_errno(getattr(errno, errno_name))
if nnp:
    PR_SET_NO_NEW_PRIVS = 38
    if ctypes.CDLL(None, use_errno=True).prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        sys.exit('unit_sandbox: prctl(PR_SET_NO_NEW_PRIVS) failed')
# The write-or-execute filter first: once the allow-list is loaded, seccomp()
# itself is refused (it is in no set the unit allows).
if mdwe:
    ctx = seccomp.seccomp_init(SCMP_ACT_ALLOW)
    both = PROT_WRITE | PROT_EXEC
    rules = [('mmap', both, both), ('mprotect', PROT_EXEC, PROT_EXEC),
             ('pkey_mprotect', PROT_EXEC, PROT_EXEC)]
    for name, mask, value in rules:
        nr = syscall_nr(name)
        if nr is not None:
            cmp = ArgCmp(2, SCMP_CMP_MASKED_EQ, mask, value)
            if seccomp.seccomp_rule_add_array(ctx, act_errno(errno.EPERM), nr, 1,
                                              ctypes.byref(cmp)) != 0:
                sys.exit(f'unit_sandbox: cannot add the write-or-execute rule for {name}')
    load(ctx)
if allowed is not None:
    ctx = seccomp.seccomp_init(refuse)
    for name in sorted(allowed):
        nr = syscall_nr(name)
        if nr is not None:
            seccomp.seccomp_rule_add_array(ctx, SCMP_ACT_ALLOW, nr, 0, None)
    # execve itself must pass for the command to start: systemd applies the
    # filter in the executor just before its execve, which @default allows.
    load(ctx)
os.execvp(argv[0], argv)
