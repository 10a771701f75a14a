// Writes a finished run as an MCAP file for Foxglove (docs/foxglove.md):
//
//   node foxglove/src/export_mcap.mjs RUN_DIR OUT.mcap
//
// (`proxsim export RUN_DIR --mcap OUT.mcap` and `proxsim run --mcap OUT.mcap`
// run this.) The file is written by @mcap/core's McapWriter through
// @mcap/nodejs's file writer, chunked and indexed, uncompressed; messages
// are JSON, each channel's schema the JSON schema @foxglove/schemas
// publishes (encoding `jsonschema`). Messages go out in time order, merged
// from the topics' own ordered streams. The file appears whole: it is
// written as OUT.mcap.tmp and renamed when complete. Beside it, the Foxglove
// layout for it (OUT.layout.json, foxglove_layout.mjs), likewise whole.
// Never through a link (the C++ writers' rule, src/core/atomic_file.h): each
// .tmp is created with O_EXCL | O_NOFOLLOW (a link planted there is refused,
// a regular file left by a killed export replaced), and the rename replaces
// a link under the final name rather than writing through it; a device,
// FIFO or folder there is refused.
// Exit 0 done; 2 bad input (the run's files, the arguments), named; 1 anything else.
import fs from 'node:fs/promises';
import { constants as fsConstants } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { McapWriter } from '@mcap/core';
import { FileHandleWritable } from '@mcap/nodejs';
import { readRunFolder, RunFolderError } from './run_folder.mjs';
import { runTopics, toNanoseconds } from './foxglove_messages.mjs';
import { layoutPath, runLayout } from './foxglove_layout.mjs';

const BAD_INPUT = 2;

/** An output proxsim will not write: a link or a special file where it would go. */
export class UnsafeOutputError extends Error {}

/** Opens `finalPath`.tmp afresh for writing, never through a link; returns [handle, tmpPath]. */
async function openTemporary(finalPath) {
  const existing = await fs.lstat(finalPath).catch(() => null);
  if (existing && !existing.isFile() && !existing.isSymbolicLink()) {
    throw new UnsafeOutputError(`${finalPath}: not a regular file; proxsim never replaces a device, FIFO or folder`);
  }
  const tmpPath = `${finalPath}.tmp`;
  const flags = fsConstants.O_WRONLY | fsConstants.O_CREAT | fsConstants.O_EXCL | fsConstants.O_NOFOLLOW;
  try {
    return [await fs.open(tmpPath, flags, 0o644), tmpPath];
  } catch (error) {
    if (error.code !== 'EEXIST') throw error;
    if (!(await fs.lstat(tmpPath)).isFile()) {
      throw new UnsafeOutputError(`${tmpPath}: a symbolic link or not a regular file; proxsim never writes `
        + 'through one (remove it)');
    }
    await fs.rm(tmpPath);  // left by a killed export
    return [await fs.open(tmpPath, flags, 0o644), tmpPath];
  }
}

/**
 * Writes the run in `runDir` to `mcapPath`, and its layout beside it; returns {messages, topics: [{topic,
 * schema, count}], start_s, end_s, layout (the layout's path)}.
 */
export async function exportRun(runDir, mcapPath) {
  const run = readRunFolder(runDir);
  const topics = runTopics(run);
  const [handle, tmpPath] = await openTemporary(mcapPath);
  const encoder = new TextEncoder();
  const counts = topics.map(() => 0);
  let first = null;
  let last = null;
  try {
    const writer = new McapWriter({ writable: new FileHandleWritable(handle) });
    await writer.start({ profile: '', library: 'proxsim export (@mcap/core)' });

    // one schema per schema name, one channel per topic
    const schemaIds = new Map();
    const channelIds = [];
    for (const { topic, schema } of topics) {
      if (!schemaIds.has(schema.title)) {
        schemaIds.set(schema.title, await writer.registerSchema({
          name: schema.title, encoding: 'jsonschema', data: encoder.encode(JSON.stringify(schema)),
        }));
      }
      channelIds.push(await writer.registerChannel({
        topic, messageEncoding: 'json', schemaId: schemaIds.get(schema.title), metadata: new Map(),
      }));
    }

    // the messages, merged in time order (a tie goes to the topic listed first)
    const heads = topics.map(({ messages }) => messages.next());
    let sequence = 0;
    for (;;) {
      let pick = -1;
      heads.forEach((head, k) => {
        if (!head.done && (pick < 0 || head.value.t_s < heads[pick].value.t_s)) pick = k;
      });
      if (pick < 0) break;
      const { t_s, message } = heads[pick].value;
      const time = toNanoseconds(t_s);
      await writer.addMessage({
        channelId: channelIds[pick], sequence, logTime: time, publishTime: time,
        data: encoder.encode(JSON.stringify(message)),
      });
      sequence += 1;
      counts[pick] += 1;
      first ??= t_s;
      last = t_s;
      heads[pick] = topics[pick].messages.next();
    }

    // what the run was, for whoever opens the file
    const inputs = run.summary.inputs ?? {};
    await writer.addMetadata({
      name: 'proxsim',
      metadata: new Map([
        ['source', String(inputs.source ?? '')], ['seed', String(inputs.seed ?? '')],
        ['proxsim_version', String(run.summary.versions?.proxsim ?? '')], ['run_dir', path.resolve(runDir)],
      ]),
    });
    await writer.end();
  } catch (error) {
    await handle.close().catch(() => {});
    await fs.rm(tmpPath, { force: true });
    throw error;
  }
  await handle.close();
  await fs.rename(tmpPath, mcapPath);
  // the layout that opens the file ready to look at
  const layout = layoutPath(mcapPath);
  const [layoutHandle, layoutTmp] = await openTemporary(layout);
  try {
    await layoutHandle.writeFile(`${JSON.stringify(runLayout(topics, (last ?? 0) - (first ?? 0)), null, 2)}\n`);
  } finally {
    await layoutHandle.close();
  }
  await fs.rename(layoutTmp, layout);
  return {
    layout,
    messages: counts.reduce((a, b) => a + b, 0),
    topics: topics.map(({ topic, schema }, k) => ({ topic, schema: schema.title, count: counts[k] })),
    start_s: first,
    end_s: last,
  };
}

async function main() {
  const [runDir, mcapPath] = process.argv.slice(2);
  if (!runDir || !mcapPath) {
    console.error('usage: node export_mcap.mjs RUN_DIR OUT.mcap');
    return BAD_INPUT;
  }
  try {
    const result = await exportRun(runDir, mcapPath);
    console.log(`mcap: ${mcapPath} — ${result.messages} messages on ${result.topics.length} topics, `
      + `t = ${result.start_s ?? 0} to ${result.end_s ?? 0} s; layout ${result.layout}`);
    return 0;
  } catch (error) {
    if (error instanceof RunFolderError) {
      console.error(`proxsim export: ${error.message}`);
      return BAD_INPUT;
    }
    if (error instanceof UnsafeOutputError) {
      console.error(`proxsim export: ${error.message}`);
      return 1;
    }
    console.error(`proxsim export: ${error.stack ?? error}`);
    return 1;
  }
}

// run as a script (not when imported)
if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) process.exitCode = await main();
