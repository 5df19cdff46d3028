// Starting `apprentice serve` for the page's tests and benchmark: on a free
// port (--port 0; the program prints its address), in a fresh scratch
// directory, stopped with SIGTERM. Shared by page_test.mjs and
// bench/serve_bench.mjs.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

export function scratchDir(prefix) {
  return fs.mkdtempSync(path.join(os.tmpdir(), prefix));
}

// The kitchen replies of kitchen_replies.txt.
export function kitchenReplies(sourceDir) {
  return fs.readFileSync(path.join(sourceDir, 'tests/serve/kitchen_replies.txt'), 'utf8')
    .split('\n').filter((line) => line.trim() !== '' && !line.startsWith('#'));
}

// Resolves to {address, port, process, output(), stop()} once the server
// prints its address.
export function startServer(binary, args) {
  return new Promise((resolve, reject) => {
    const child = spawn(binary, ['serve', '--port', '0', ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '', err = '';
    const timer = setTimeout(() => reject(new Error('serve printed no address in 20 s: ' + out + err)), 20000);
    child.stdout.on('data', (d) => {
      out += d;
      const m = /open (http:\/\/[^\s]+)/.exec(out);
      if (m) {
        clearTimeout(timer);
        const address = m[1];
        resolve({
          address,
          port: Number(new URL(address).port),
          process: child,
          output: () => out + err,
          stop: () => new Promise((done) => {
            if (child.exitCode !== null) return done(child.exitCode);
            child.on('exit', (code) => done(code));
            child.kill('SIGTERM');
          }),
        });
      }
    });
    child.stderr.on('data', (d) => { err += d; });
    child.on('exit', (code) => { clearTimeout(timer); reject(new Error('serve exited with ' + code + ': ' + out + err)); });
  });
}

// Debian's chromium, headless, as the project runs it everywhere: never a
// downloaded browser.
export const chromiumFlags = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];
