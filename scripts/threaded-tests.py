#!/usr/bin/env python3
"""Which tests start a thread: runs every CTest test of BUILD_DIR under strace (clones with
CLONE_THREAD, child processes followed) and compares with the tests labelled `threads`
(tests/CMakeLists.txt, AWB_THREADED_TESTS), the suite ThreadSanitizer runs. Exit 1 when a test
starts threads without the label.

    python3 scripts/threaded-tests.py build [-R REGEX]

About as long as the suite under strace (6 minutes on the 2-core CI machine); not part of CI."""
import argparse, json, os, re, subprocess, sys, tempfile

ap = argparse.ArgumentParser()
ap.add_argument('build')
ap.add_argument('-R', dest='regex', default='')
args = ap.parse_args()
info = json.loads(subprocess.run(['ctest', '--test-dir', args.build, '--show-only=json-v1'],
                                 check=True, capture_output=True, text=True).stdout)
missing, labelled_idle = [], []
with tempfile.TemporaryDirectory() as tmp:
    for t in info['tests']:
        name = t['name']
        if args.regex and not re.search(args.regex, name):
            continue
        props = {p['name']: p['value'] for p in t.get('properties', [])}
        env = dict(os.environ)
        for kv in props.get('ENVIRONMENT', []):
            k, v = kv.split('=', 1)
            env[k] = v
        log = os.path.join(tmp, 'strace')
        subprocess.run(['strace', '-f', '-qq', '-e', 'trace=clone,clone3', '-o', log] + t['command'],
                       env=env, cwd=props.get('WORKING_DIRECTORY', args.build),
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        threads = open(log).read().count('CLONE_THREAD')
        labelled = 'threads' in props.get('LABELS', [])
        print(f'{name}: {threads} threads started{", labelled threads" if labelled else ""}',
              flush=True)
        if threads and not labelled:
            missing.append(name)
        if labelled and not threads:
            labelled_idle.append(name)
if labelled_idle:
    print('labelled `threads` but started none:', ' '.join(labelled_idle))
if missing:
    print('start threads but are not labelled `threads` (add them to AWB_THREADED_TESTS):',
          ' '.join(missing))
    sys.exit(1)
print('every test that starts a thread is labelled `threads`')
