// Runs the Khronos glTF validator (npm gltf-validator) on one .glb or .gltf
// file and prints its report summary and every issue. Exits 1 when the
// report has errors (warnings, infos and hints are printed but allowed),
// 2 when the file cannot be read or the validator cannot parse it at all.
//
// usage: node validate_gltf.mjs FILE.{glb,gltf}
import { readFile } from 'node:fs/promises';
import path from 'node:path';

const severityNames = ['error', 'warning', 'info', 'hint'];

// The validator lives in tests/external/node_modules (npm ci --prefix
// tests/external, run by scripts/setup.sh); say so if it is not there.
async function loadValidator() {
    try {
        return (await import('gltf-validator')).default;
    } catch (error) {
        console.error('validate_gltf: the npm package gltf-validator is not installed ' +
                      `(${error.code ?? error.message}); run scripts/setup.sh ` +
                      '(npm ci --prefix tests/external)');
        return null;
    }
}

async function main() {
    const validator = await loadValidator();
    if (!validator)
        return 2;
    const file = process.argv[2];
    if (!file || process.argv.length > 3) {
        console.error('usage: node validate_gltf.mjs FILE.{glb,gltf}');
        return 2;
    }
    let bytes;
    try {
        bytes = new Uint8Array(await readFile(file));
    } catch (error) {
        console.error(`validate_gltf: cannot read ${file}: ${error.message}`);
        return 2;
    }
    const extension = path.extname(file).toLowerCase();
    let report;
    try {
        report = await validator.validateBytes(bytes, {
            uri: path.basename(file),
            format: extension === '.glb' ? 'glb' : extension === '.gltf' ? 'gltf' : undefined,
            maxIssues: 0,  // report everything
            writeTimestamp: false,
            // .gltf buffers and images live beside the file: load them so
            // that their contents are validated too (accessors, weights).
            externalResourceFunction: async (uri) => {
                const resource = path.resolve(path.dirname(file), decodeURIComponent(uri));
                return new Uint8Array(await readFile(resource));
            },
        });
    } catch (error) {
        console.error(`validate_gltf: the validator could not read ${file}: ${error}`);
        return 2;
    }

    const issues = report.issues;
    const generator = report.info?.generator ?? 'unknown generator';
    console.log(`${file}: glTF validator ${report.validatorVersion} (${generator})`);
    console.log(`  errors ${issues.numErrors}, warnings ${issues.numWarnings}, ` +
                `infos ${issues.numInfos}, hints ${issues.numHints}`);
    if (report.info) {
        const info = report.info;
        console.log(`  ${info.drawCallCount ?? 0} draw calls, ${info.totalVertexCount ?? 0} vertices, ` +
                    `${info.totalTriangleCount ?? 0} triangles, ${info.animationCount ?? 0} animations, ` +
                    `skins ${info.hasSkins ? 'yes' : 'no'}`);
    }
    // Group repeated codes (one per vertex would flood the log): the count
    // and the first three pointers per code and severity.
    const groups = new Map();
    for (const message of issues.messages) {
        const key = `${message.severity}:${message.code}`;
        if (!groups.has(key))
            groups.set(key, { severity: message.severity, code: message.code, text: message.message, where: [] });
        groups.get(key).where.push(message.pointer ?? (message.offset !== undefined ? `byte ${message.offset}` : ''));
    }
    for (const group of [...groups.values()].sort((a, b) => a.severity - b.severity)) {
        const shown = group.where.slice(0, 3).filter(Boolean).join(', ');
        const more = group.where.length > 3 ? ` and ${group.where.length - 3} more` : '';
        console.log(`  ${severityNames[group.severity] ?? 'issue'} ${group.code} x${group.where.length}: ` +
                    `${group.text}${shown ? ` [${shown}${more}]` : ''}`);
    }
    if (issues.numErrors > 0) {
        console.log(`FAIL: ${issues.numErrors} validator error(s) in ${file}`);
        return 1;
    }
    console.log(`PASS: no validator errors in ${file}`);
    return 0;
}

process.exitCode = await main();
