// Entry point: the page's data (embedded JSON) says what to show.
import { el } from './util.js';
import { showExploration } from './view_exploration.js';
import { showCounterexample } from './view_counterexample.js';
import { showHandshake } from './view_handshake.js';
import { showMission } from './view_mission.js';
import { showFsm } from './view_fsm.js';
import { showEditor } from './editor.js';
import { showMissionEditor } from './mission_editor.js';
import { showLive } from './live.js';

const shows = {
  exploration: showExploration,
  counterexample: showCounterexample,
  handshake: showHandshake,
  mission: showMission,
  fsm: showFsm,
  editor: showEditor,
  'mission-editor': showMissionEditor,
  live: showLive,
};

const app = document.getElementById('app');
app.replaceChildren();
try {
  const data = JSON.parse(document.getElementById('swarmcheck-data').textContent);
  shows[data.kind](app, data);
  document.body.dataset.ready = 'yes';
} catch (e) {
  app.append(el('pre', { class: 'status error', text: `swarmcheck: this page failed: ${e.stack || e}` }));
  document.body.dataset.ready = 'error';
}
