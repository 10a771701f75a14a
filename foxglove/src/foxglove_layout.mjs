// The Foxglove layout written beside a run's MCAP file (docs/foxglove.md):
// import it in Foxglove (Layouts → Import from file) and the file opens ready
// to look at — a 3D panel on `world` with the profile kept for the whole run,
// one Plot panel per sensor of its distance `d_m`, and a Log panel of
// `/events`. It is a layout as Foxglove exports one: `configById` (each panel
// as `Type!id` and its settings), the panels' `layout` as a tree of splits,
// `globalVariables`, `userNodes`, `playbackConfig`.

/** The layout's file beside the MCAP file: `run.mcap` → `run.layout.json` (`run` → `run.layout.json`). */
export function layoutPath(mcapPath) {
  return `${mcapPath.replace(/\.mcap$/i, '')}.layout.json`;
}

/**
 * A topic in a Foxglove message path: bare when it is plain, else quoted
 * (a sensor's name may hold spaces, dots or quotes).
 */
function topicInPath(topic) {
  return /^[A-Za-z0-9_/]+$/.test(topic) ? topic : `"${topic.replace(/\\/g, '\\\\').replace(/"/g, '\\"')}"`;
}

/** Panels split evenly along `direction` ('row' or 'column'): a tree of {first, second}. */
function split(ids, direction) {
  if (ids.length === 1) return ids[0];
  return { first: ids[0], second: split(ids.slice(1), direction), direction, splitPercentage: 100 / ids.length };
}

/**
 * The layout for a run's MCAP file, from the topics it holds ({topic} of
 * runTopics) and the run's duration (the profile's decay time: its points
 * stay for the whole run, as the viewer grows it).
 */
export function runLayout(topics, durationS) {
  const names = new Set(topics.map(({ topic }) => topic));
  const readings = [...names].filter((t) => /^\/sensors\/.*\/reading$/.test(t));
  const configById = {};

  // the 3D view: the scene, the robot, the rays and the profile in the world frame
  const rays = readings.map((t) => t.replace(/reading$/, 'ray'));
  const shown = ['/scene', '/robot', '/profile', '/terrain/map', '/terrain/hazards', ...rays];
  const topicSettings = {};
  for (const topic of shown.filter((t) => names.has(t))) topicSettings[topic] = { visible: true };
  if (topicSettings['/profile']) {
    Object.assign(topicSettings['/profile'], { decayTime: Math.max(durationS, 1), pointSize: 3 });
  }
  configById['3D!world'] = { followTf: 'world', followMode: 'follow-pose', topics: topicSettings, layers: {} };

  // a plot of each sensor's distance over time
  const plots = readings.map((topic, k) => {
    const sensor = topic.slice('/sensors/'.length, -'/reading'.length);
    const id = `Plot!sensor${k}`;
    configById[id] = {
      foxglovePanelTitle: `${sensor}: d_m`,
      paths: [{ value: `${topicInPath(topic)}.d_m`, enabled: true, timestampMethod: 'receiveTime', label: sensor }],
      showLegend: true,
      showXAxisLabels: true,
      showYAxisLabels: true,
      isSynced: true,
      xAxisVal: 'timestamp',
    };
    return id;
  });

  // the run's events: warnings, what the strategy decided, the outcome
  const side = [...plots];
  if (names.has('/events')) {
    configById['RosOut!events'] = { topicToRender: '/events', minLogLevel: 1, searchTerms: [] };
    side.push('RosOut!events');
  }

  return {
    configById,
    globalVariables: {},
    userNodes: {},
    playbackConfig: { speed: 1 },
    layout: side.length === 0 ? '3D!world'
      : { first: '3D!world', second: split(side, 'column'), direction: 'row', splitPercentage: 60 },
  };
}
