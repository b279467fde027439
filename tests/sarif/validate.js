// Validates SARIF files against the published SARIF 2.1.0 JSON schema (the
// OASIS rtm.5 schema shipped in @microsoft/jest-sarif) with ajv, plus the
// extra rules GitHub code scanning applies. With --json-schema SCHEMA, validates
// shaderport JSON output against SCHEMA instead.
// Usage: node validate.js [--json-schema SCHEMA] FILE...
'use strict';

const fs = require('fs');
const path = require('path');
const AjvDraft04 = require('ajv-draft-04');
const Ajv = require('ajv');
const addFormats = require('ajv-formats');

const kSarifSchema = require.resolve('@microsoft/jest-sarif/lib/schemas/sarif-2.1.0-rtm.5.json');

function compileSarif() {
  // unicodeRegExp: false because the published schema's `language` pattern has a
  // stray ']' that only non-unicode regular expressions accept.
  const ajv = new AjvDraft04({allErrors: true, strict: false, unicodeRegExp: false});
  addFormats(ajv);
  return ajv.compile(JSON.parse(fs.readFileSync(kSarifSchema, 'utf8')));
}

function compileJsonSchema(schemaPath) {
  const ajv = new Ajv({allErrors: true, strict: true});
  addFormats(ajv);
  return ajv.compile(JSON.parse(fs.readFileSync(schemaPath, 'utf8')));
}

// What GitHub code scanning requires beyond the schema.
function githubProblems(log) {
  const problems = [];
  if (log.version !== '2.1.0') problems.push('version must be 2.1.0');
  for (const [r, run] of (log.runs || []).entries()) {
    const rules = (run.tool && run.tool.driver && run.tool.driver.rules) || [];
    const ids = rules.map((rule) => rule.id);
    if (new Set(ids).size !== ids.length) problems.push(`run ${r}: duplicate rule ids`);
    for (const [i, result] of (run.results || []).entries()) {
      const where = `run ${r} result ${i}`;
      if (!result.ruleId) problems.push(`${where}: no ruleId`);
      if (result.ruleIndex !== undefined && ids[result.ruleIndex] !== result.ruleId) {
        problems.push(`${where}: ruleIndex ${result.ruleIndex} is not ${result.ruleId}`);
      }
      if (!result.message || typeof result.message.text !== 'string') {
        problems.push(`${where}: no message.text`);
      }
      const locations = result.locations || [];
      if (locations.length === 0) problems.push(`${where}: no location`);
      for (const location of locations) {
        const physical = location.physicalLocation;
        if (!physical || !physical.artifactLocation || !physical.artifactLocation.uri) {
          problems.push(`${where}: a location without physicalLocation.artifactLocation.uri`);
        }
      }
    }
  }
  return problems;
}

function checkSarif(validate, log) {
  const problems = [];
  if (!validate(log)) {
    for (const error of validate.errors) problems.push(`${error.instancePath} ${error.message}`);
  }
  return problems.concat(githubProblems(log));
}

// The validator must reject known-bad input before its "valid" means anything.
function selfTest(validate) {
  const good = {
    $schema: 'https://json.schemastore.org/sarif-2.1.0.json',
    version: '2.1.0',
    runs: [{
      tool: {driver: {name: 't', rules: [{id: 'a/b'}]}},
      results: [{
        ruleId: 'a/b', ruleIndex: 0, level: 'error', message: {text: 'm'},
        locations: [{physicalLocation: {artifactLocation: {uri: 'a.frag'},
                                        region: {startLine: 1, startColumn: 1}}}],
      }],
    }],
  };
  if (checkSarif(validate, good).length !== 0) {
    throw new Error('self-test: a valid SARIF log was rejected: ' + checkSarif(validate, good));
  }
  const breakers = {
    'wrong version': (log) => { log.version = '2.2.0'; },
    'unknown level': (log) => { log.runs[0].results[0].level = 'fatal'; },
    'line 0': (log) => { log.runs[0].results[0].locations[0].physicalLocation.region.startLine = 0; },
    'unknown property': (log) => { log.runs[0].results[0].severity = 'error'; },
    'no tool': (log) => { delete log.runs[0].tool; },
    'bad ruleIndex': (log) => { log.runs[0].results[0].ruleIndex = 3; },
  };
  for (const [name, breakIt] of Object.entries(breakers)) {
    const broken = JSON.parse(JSON.stringify(good));
    breakIt(broken);
    const problems = checkSarif(validate, broken);
    if (problems.length === 0) throw new Error(`self-test: a broken log (${name}) was accepted`);
    console.log(`self-test: broken SARIF (${name}) rejected: ${problems[0]}`);
  }
}

function main(argv) {
  let jsonSchema = null;
  const files = [];
  for (let i = 0; i < argv.length; ++i) {
    if (argv[i] === '--json-schema') jsonSchema = argv[++i];
    else files.push(argv[i]);
  }
  if (files.length === 0) {
    console.error('usage: validate.js [--json-schema SCHEMA] FILE...');
    return 2;
  }
  let validate;
  if (jsonSchema) {
    validate = compileJsonSchema(jsonSchema);
  } else {
    validate = compileSarif();
    selfTest(validate);
  }
  let failed = 0;
  for (const file of files) {
    const document = JSON.parse(fs.readFileSync(file, 'utf8'));
    const problems = jsonSchema
      ? (validate(document) ? [] : validate.errors.map((e) => `${e.instancePath} ${e.message}`))
      : checkSarif(validate, document);
    if (problems.length === 0) {
      console.log(`valid: ${path.basename(file)}`);
    } else {
      ++failed;
      console.log(`INVALID: ${file}`);
      for (const problem of problems) console.log(`  ${problem}`);
    }
  }
  console.log(`${files.length - failed} passed, ${failed} failed`);
  return failed === 0 ? 0 : 1;
}

try {
  process.exitCode = main(process.argv.slice(2));
} catch (error) {
  console.error(String(error.stack || error));
  process.exitCode = 2;
}
