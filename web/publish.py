#!/usr/bin/env python3
"""Publishes the browser app into its folder (build/web) as a web server should serve it.

    web/publish.py OUT NAME=PATH...

Every NAME below comes from its PATH (the linked page, the generated texts and icons, the
sources in web/). The files that change with a build are published under a name that carries
their content's hash (swarmlab.3f2a9c1b.wasm), so that a server may let browsers keep them
forever (web/serve/Caddyfile); the files a visitor reaches by a fixed address (index.html,
the manifest, the service worker, the example course page) keep their names and are
revalidated at every visit, and they name the hashed files:
- in web/shell.html (index.html) and web/manifest.webmanifest, @NAME@ is NAME's published
  name; in the page, @SWARMLAB_FILES@ is the map of every hashed NAME to its published name
  (window.swarmlabFiles: the wasm and the fonts fetched on demand find theirs there) and
  @SWARMLAB_WASM_BYTES@ the wasm's size (the download's progress: a compressed response's
  Content-Length is not the size of what it holds), and @SWARMLAB_INLINE_SCRIPTS@ the hashes
  of its inline scripts once filled in, for its Content-Security-Policy;
- examples/course.html is copied as it is, once its Content-Security-Policy is seen to name its
  inline script's hash (a page edited without the new hash would run no script);
- in web/service_worker.js, @SWARMLAB_WEB_VERSION@ is a hash of everything published,
  @SWARMLAB_WEB_FILES@ what the worker stores at install and @SWARMLAB_WEB_ON_DEMAND@ what the
  page fetches only when needed.
Beside each text file goes a .br (Debian's brotli, best quality) and a .gz (gzip -9) copy,
which the server sends to browsers that accept them. A hashed file already published is
neither copied nor compressed again. What an earlier publication wrote and this one does not
(an older build's hashed files, the unhashed names of earlier builds) is removed.
"""
import base64
import hashlib
import json
import os
import re
import subprocess
import sys

# NAME: (hashed, stored by the service worker at install). Hashed and not stored: fetched on
# demand (the worker keeps it once fetched).
FILES = {
    'index.html': (False, True),
    'manifest.webmanifest': (False, True),
    'page_text.js': (True, True),
    'page_texts.js': (True, True),
    'swarmlab.js': (True, True),
    'swarmlab.wasm': (True, True),
    'offline.js': (True, True),
    'icon-192.png': (True, True),
    'icon-512.png': (True, True),
    'fonts/noto-sans-sc-subset.otf': (True, False),
    'examples/course.html': (False, False),
    'service_worker.js': (False, False),  # the browser fetches it itself, past every cache
}
# Compressed copies for these; images are compressed already.
COMPRESSED = ('.html', '.js', '.wasm', '.webmanifest', '.otf', '.json')
HASH_DIGITS = 8
TOKEN = re.compile(r'@([A-Za-z0-9_./-]+)@')
RECORD = '.published'  # what this publication wrote, for the next one to clean up after


def fail(message):
    sys.exit(f'publish: {message}')


def hashed_name(name, content):
    stem, ext = os.path.splitext(name)
    return f'{stem}.{hashlib.sha256(content).hexdigest()[:HASH_DIGITS]}{ext}'


def write_if_changed(path, content):
    """Writes through a temporary file (never half a file under a served name); True if the
    content changed."""
    try:
        with open(path, 'rb') as f:
            if f.read() == content:
                return False
    except FileNotFoundError:
        pass
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path + '.tmp', 'wb') as f:
        f.write(content)
    os.replace(path + '.tmp', path)
    return True


def compress(path, changed):
    """The .br and .gz copies beside path (made again only if it changed or one is missing);
    their paths."""
    if not path.endswith(COMPRESSED):
        return []
    commands = {'.br': ['brotli', '--best', '--stdout', path],
                '.gz': ['gzip', '-9', '--no-name', '--stdout', path]}
    for ext, command in commands.items():
        out = path + ext
        if changed or not os.path.exists(out):
            with open(out + '.tmp', 'wb') as f:
                subprocess.run(command, stdout=f, check=True)
            os.replace(out + '.tmp', out)
    return [path + ext for ext in commands]


def inline_script_hashes(text):
    """The CSP sources ('sha256-...') of a page's inline scripts, each as the browser hashes it."""
    scripts = re.findall(r'^<script>(.*?)</script>', text, re.S | re.M)
    return ' '.join("'sha256-%s'" % base64.b64encode(hashlib.sha256(s.encode()).digest()).decode()
                    for s in scripts)


def fill(name, text, tokens):
    def one(match):
        key = match.group(1)
        if key not in tokens:
            fail(f'{name}: @{key}@ names nothing published')
        return tokens[key]
    return TOKEN.sub(one, text)


def main(argv):
    if len(argv) < 2:
        fail(__doc__.strip().splitlines()[2].strip())
    out = os.path.abspath(argv[0])
    sources = dict(arg.split('=', 1) for arg in argv[1:])
    missing = [n for n in FILES if n not in sources or not os.path.isfile(sources[n])]
    if missing:
        fail('missing ' + ', '.join(f'{n} ({sources.get(n, "not given")})' for n in missing))

    published = {}   # NAME -> published name
    contents = {}    # published name -> bytes
    for name, (is_hashed, _) in FILES.items():
        if is_hashed:
            with open(sources[name], 'rb') as f:
                content = f.read()
            published[name] = hashed_name(name, content)
            contents[published[name]] = content

    tokens = dict(published)
    tokens['index.html'] = 'index.html'
    tokens['manifest.webmanifest'] = 'manifest.webmanifest'
    tokens['SWARMLAB_FILES'] = json.dumps(published, sort_keys=True)
    tokens['SWARMLAB_WASM_BYTES'] = str(len(contents[published['swarmlab.wasm']]))
    tokens['SWARMLAB_INLINE_SCRIPTS'] = '@SWARMLAB_INLINE_SCRIPTS@'  # once the rest is in
    for name, source in (('index.html', sources['index.html']),
                         ('manifest.webmanifest', sources['manifest.webmanifest'])):
        with open(source, encoding='utf-8') as f:
            text = fill(name, f.read(), tokens)
        contents[name] = text.replace('@SWARMLAB_INLINE_SCRIPTS@', inline_script_hashes(text)).encode()
    with open(sources['examples/course.html'], 'rb') as f:
        contents['examples/course.html'] = f.read()
    course = contents['examples/course.html'].decode()
    if "script-src %s;" % inline_script_hashes(course) not in course:
        fail('examples/course.html: its Content-Security-Policy does not say script-src %s; '
             '(the hash of its inline script)' % inline_script_hashes(course))

    # The worker's version: every published name and content, and the worker's own code.
    with open(sources['service_worker.js'], encoding='utf-8') as f:
        worker = f.read()
    digest = hashlib.sha256()
    for name in sorted(contents):
        digest.update(f'{name} {hashlib.sha256(contents[name]).hexdigest()}\n'.encode())
    digest.update(worker.encode())
    listed = lambda names: ', '.join(f"'{n}'" for n in names)
    precached = [published.get(n, n) for n, (_, stored) in FILES.items() if stored]
    on_demand = [published[n] for n, (is_hashed, stored) in FILES.items() if is_hashed and not stored]
    worker = fill('service_worker.js', worker, {
        'SWARMLAB_WEB_VERSION': digest.hexdigest()[:16],
        'SWARMLAB_WEB_FILES': listed(precached),
        'SWARMLAB_WEB_ON_DEMAND': listed(on_demand)})
    contents['service_worker.js'] = worker.encode()

    written = []
    hashed_names = set(published.values())
    for name, content in contents.items():
        path = os.path.join(out, name)
        if name in hashed_names and os.path.exists(path):
            changed = False  # a hashed name is its content: present means done
        else:
            changed = write_if_changed(path, content)
        written.append(name)
        written += [os.path.relpath(p, out) for p in compress(path, changed)]

    # Clean up after earlier publications: what the last one wrote and this one did not, and
    # the unhashed names that builds before content hashing wrote.
    record = os.path.join(out, RECORD)
    stale = set()
    if os.path.exists(record):
        with open(record, encoding='utf-8') as f:
            stale = set(f.read().split())
    for name in published:
        stale |= {name, name + '.br', name + '.gz'}
    for name in sorted(stale - set(written)):
        path = os.path.join(out, name)
        if os.path.isfile(path):
            os.remove(path)
    write_if_changed(record, ''.join(n + '\n' for n in sorted(written)).encode())


if __name__ == '__main__':
    main(sys.argv[1:])
