// Routes in the viewer: a click on "Plan a route", then two clicks on the
// map give the shortest route between the two points through the Area
// Graph. The graph of corners and links is the C++ router's
// (tools/route/area_router.h, run.route_graph in viewer_page.proto): the page
// only links the two points to the corners they see and searches the rest.
// A point outside every area starts from the nearest area within 1 m, as
// ag-route does; the page's test for "sees" is stricter than the router's (a
// line that touches a wall on its way does not count), so a route here may
// be a little longer than ag-route's, never one that crosses a wall.
'use strict';

function areagraphRoutes(context) {
  const { state, resolution, svg, html } = context;
  const EPS = 0.02; // pixels: the page's coordinates are rounded to 0.01 px
  const prepared = new Map(); // run -> its route graph, ready to search
  let active = false;
  let ends = []; // up to two {x, y} in map pixels
  let result = null; // {run, points: [[x, y], ...], metres}

  const style = html('style', {}, document.head);
  style.textContent = '.route polyline { fill: none; stroke: #ff6a00; stroke-width: 4; stroke-linejoin: round;' +
    ' vector-effect: non-scaling-stroke; pointer-events: none; }' +
    ' .route circle { stroke: #fff; stroke-width: 2; pointer-events: none; }' +
    ' .route-start { fill: #1a9c1a; } .route-goal { fill: #d01c1c; }';
  const section = html('section', { id: 'route-section' });
  const layers = document.getElementById('layers-section');
  layers.parentNode.insertBefore(section, layers);
  html('h2', {}, section, 'Route');
  const button = html('button', { type: 'button', id: 'route-button' }, section, 'Plan a route');
  const status = html('div', { id: 'route-status', class: 'muted' }, section,
    'Plan a route, then click the start and the goal on the map.');
  button.addEventListener('click', () => {
    active = !active;
    ends = [];
    result = null;
    button.textContent = active ? 'Stop planning' : 'Plan a route';
    say(active ? 'Click the start.' : 'Plan a route, then click the start and the goal on the map.');
    draw();
  });

  function say(text) {
    status.textContent = text;
  }

  // ---- geometry, in map pixels --------------------------------------------

  function prepare(graph) {
    const corners = graph.corners || [];
    const count = corners.length / 2;
    const neighbours = Array.from({ length: count }, () => []);
    const links = graph.links || [];
    for (let i = 0; i < links.length; i += 2) {
      neighbours[links[i]].push(links[i + 1]);
      neighbours[links[i + 1]].push(links[i]);
    }
    const areas = (graph.areas || []).map((area) => {
      const rings = (area.rings || []).map((ring) => ring.xy || []);
      const box = [Infinity, Infinity, -Infinity, -Infinity];
      for (const ring of rings) {
        for (let i = 0; i < ring.length; i += 2) {
          box[0] = Math.min(box[0], ring[i]); box[1] = Math.min(box[1], ring[i + 1]);
          box[2] = Math.max(box[2], ring[i]); box[3] = Math.max(box[3], ring[i + 1]);
        }
      }
      return { rings, box, corners: area.corners || [] };
    });
    return { corners, count, neighbours, areas, walls: graph.walls || [], kinds: graph.corner_kinds || [], cornerWalls: graph.corner_walls || [] };
  }

  // Whether a route may come to corner c from (dx, dy) (from the corner
  // towards the other point) and bend there, as the router decides it
  // (AreaRouter::Admits; in pixels, y down, so turns run the other way).
  function admits(g, c, dx, dy) {
    const kind = g.kinds[c] || 0;
    if (kind === 0) return true;
    const w = g.cornerWalls;
    const a = dx * w[4 * c + 1] - dy * w[4 * c], b = dx * w[4 * c + 3] - dy * w[4 * c + 2];
    const parallel = 1e-12 * Math.hypot(dx, dy);
    if (kind === 2) return !(a * b < 0 && Math.abs(a) > parallel && Math.abs(b) > parallel);
    return a >= -parallel && b <= parallel;
  }

  function inside(rings, x, y) {
    let odd = false;
    for (const ring of rings) {
      for (let i = 0, j = ring.length - 2; i < ring.length; j = i, i += 2) {
        const ax = ring[i], ay = ring[i + 1], bx = ring[j], by = ring[j + 1];
        if ((ay > y) !== (by > y) && x < (bx - ax) * (y - ay) / (by - ay) + ax) odd = !odd;
      }
    }
    return odd;
  }

  function segmentDistance(px, py, ax, ay, bx, by) {
    const dx = bx - ax, dy = by - ay;
    const length2 = dx * dx + dy * dy;
    const t = length2 > 0 ? Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / length2)) : 0;
    return { distance: Math.hypot(ax + t * dx - px, ay + t * dy - py), x: ax + t * dx, y: ay + t * dy };
  }

  // The area holding the point (its outline within EPS counts), or -1.
  function areaAt(g, x, y) {
    for (let a = 0; a < g.areas.length; a++) {
      const { box, rings } = g.areas[a];
      if (x < box[0] - EPS || y < box[1] - EPS || x > box[2] + EPS || y > box[3] + EPS) continue;
      if (inside(rings, x, y)) return a;
      for (const ring of rings) {
        for (let i = 0, j = ring.length - 2; i < ring.length; j = i, i += 2) {
          if (segmentDistance(x, y, ring[i], ring[i + 1], ring[j], ring[j + 1]).distance <= EPS) return a;
        }
      }
    }
    return -1;
  }

  // The nearest point on a wall within maxPx, or null.
  function nearestWallPoint(g, x, y, maxPx) {
    let best = null;
    const w = g.walls;
    for (let i = 0; i < w.length; i += 4) {
      const near = segmentDistance(x, y, w[i], w[i + 1], w[i + 2], w[i + 3]);
      if (near.distance <= maxPx && (!best || near.distance < best.distance)) best = near;
    }
    return best;
  }

  function cross(ax, ay, bx, by, cx, cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  }

  // Whether the straight line from a to b stays in an area and meets no wall
  // except at its two ends.
  function sees(g, ax, ay, bx, by) {
    const length = Math.hypot(bx - ax, by - ay);
    if (length <= EPS) return true;
    const w = g.walls;
    const minX = Math.min(ax, bx) - EPS, maxX = Math.max(ax, bx) + EPS;
    const minY = Math.min(ay, by) - EPS, maxY = Math.max(ay, by) + EPS;
    const awayFromEnds = (x, y) => Math.hypot(x - ax, y - ay) > EPS && Math.hypot(x - bx, y - by) > EPS;
    for (let i = 0; i < w.length; i += 4) {
      const x1 = w[i], y1 = w[i + 1], x2 = w[i + 2], y2 = w[i + 3];
      if (Math.max(x1, x2) < minX || Math.min(x1, x2) > maxX || Math.max(y1, y2) < minY || Math.min(y1, y2) > maxY) continue;
      // A wall's end on the way.
      for (const [x, y] of [[x1, y1], [x2, y2]]) {
        if (segmentDistance(x, y, ax, ay, bx, by).distance <= EPS / 2 && awayFromEnds(x, y)) return false;
      }
      // A wall crossed.
      const d1 = cross(ax, ay, bx, by, x1, y1) / length, d2 = cross(ax, ay, bx, by, x2, y2) / length;
      if ((d1 > EPS / 2 && d2 < -EPS / 2) || (d1 < -EPS / 2 && d2 > EPS / 2)) {
        const wall = Math.hypot(x2 - x1, y2 - y1);
        const d3 = cross(x1, y1, x2, y2, ax, ay) / wall, d4 = cross(x1, y1, x2, y2, bx, by) / wall;
        if ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)) {
          const t = d3 / (d3 - d4);
          if (awayFromEnds(ax + t * (bx - ax), ay + t * (by - ay))) return false;
        }
      }
    }
    return areaAt(g, (ax + bx) / 2, (ay + by) / 2) >= 0;
  }

  // The point itself inside an area, or the nearest point of one within 1 m.
  function entry(g, point) {
    const area = areaAt(g, point.x, point.y);
    if (area >= 0) return { x: point.x, y: point.y, area, snapped: false };
    const near = nearestWallPoint(g, point.x, point.y, 1 / resolution);
    if (!near) return null;
    return { x: near.x, y: near.y, area: areaAt(g, near.x, near.y), snapped: true };
  }

  // Dijkstra's algorithm from the start over the corners to the goal.
  function shortest(g, start, goal) {
    const corner = (c) => [g.corners[2 * c], g.corners[2 * c + 1]];
    if (sees(g, start.x, start.y, goal.x, goal.y)) return [[start.x, start.y], [goal.x, goal.y]];
    const goalNode = g.count;
    const toGoal = new Map();
    for (const c of g.areas[goal.area].corners) {
      const [x, y] = corner(c);
      if (admits(g, c, goal.x - x, goal.y - y) && sees(g, goal.x, goal.y, x, y)) toGoal.set(c, Math.hypot(x - goal.x, y - goal.y));
    }
    const best = new Float64Array(g.count + 1).fill(Infinity);
    const parent = new Int32Array(g.count + 1).fill(-1);
    const done = new Uint8Array(g.count + 1);
    const heap = [];
    const push = (node, length) => {
      heap.push([length, node]);
      for (let i = heap.length - 1; i > 0;) {
        const up = (i - 1) >> 1;
        if (heap[up][0] <= heap[i][0]) break;
        [heap[up], heap[i]] = [heap[i], heap[up]];
        i = up;
      }
    };
    const pop = () => {
      const top = heap[0], last = heap.pop();
      if (heap.length) {
        heap[0] = last;
        for (let i = 0; ;) {
          const l = 2 * i + 1, r = l + 1;
          let m = i;
          if (l < heap.length && heap[l][0] < heap[m][0]) m = l;
          if (r < heap.length && heap[r][0] < heap[m][0]) m = r;
          if (m === i) break;
          [heap[m], heap[i]] = [heap[i], heap[m]];
          i = m;
        }
      }
      return top;
    };
    const reach = (node, length, from) => {
      if (length >= best[node]) return;
      best[node] = length;
      parent[node] = from;
      push(node, length);
    };
    for (const c of g.areas[start.area].corners) {
      const [x, y] = corner(c);
      if (admits(g, c, start.x - x, start.y - y) && sees(g, start.x, start.y, x, y)) reach(c, Math.hypot(x - start.x, y - start.y), -1);
    }
    while (heap.length) {
      const node = pop()[1];
      if (done[node]) continue;
      done[node] = 1;
      if (node === goalNode) break;
      const [x, y] = corner(node);
      if (toGoal.has(node)) reach(goalNode, best[node] + toGoal.get(node), node);
      for (const next of g.neighbours[node]) {
        const [nx, ny] = corner(next);
        if (!done[next]) reach(next, best[node] + Math.hypot(nx - x, ny - y), node);
      }
    }
    if (!done[goalNode]) return null;
    const points = [[goal.x, goal.y]];
    for (let node = parent[goalNode]; node >= 0; node = parent[node]) points.push(corner(node));
    points.push([start.x, start.y]);
    return points.reverse();
  }

  function plan(run) {
    if (!run.route_graph) return { why: 'This page holds no route graph (an Area Graph without polygons in metres).' };
    if (!prepared.has(run)) prepared.set(run, prepare(run.route_graph));
    const g = prepared.get(run);
    const [start, goal] = ends.map((point) => entry(g, point));
    if (!start) return { why: 'The start is more than 1 m from every area.' };
    if (!goal) return { why: 'The goal is more than 1 m from every area.' };
    const inner = shortest(g, start, goal);
    if (!inner) return { why: 'No route joins the start and the goal.' };
    const points = (start.snapped ? [[ends[0].x, ends[0].y]] : []).concat(inner,
      goal.snapped ? [[ends[1].x, ends[1].y]] : []);
    let pixels = 0;
    for (let i = 1; i < points.length; i++) pixels += Math.hypot(points[i][0] - points[i - 1][0], points[i][1] - points[i - 1][1]);
    return { run, points, metres: pixels * resolution, bends: inner.length - 2 };
  }

  // ---- drawing ------------------------------------------------------------------

  function draw() {
    for (const view of context.views()) {
      const old = view.viewport.querySelector('g.route');
      if (old) old.remove();
      const group = svg('g', { class: 'route' }, view.viewport);
      if (result && result.run === view.run) {
        group.dataset.lengthM = result.metres.toFixed(3);
        svg('polyline', { points: result.points.map((p) => p.join(',')).join(' ') }, group);
      }
      ends.forEach((end, index) => {
        svg('circle', { cx: end.x, cy: end.y, r: 6 / state.k, 'data-r': 6, class: index ? 'route-goal' : 'route-start' }, group);
      });
    }
  }

  return {
    // Takes a click on a view when planning: true when it used it.
    click(view, event) {
      if (!active) return false;
      const box = view.svg.getBoundingClientRect();
      const point = { x: (event.clientX - box.left - state.tx) / state.k, y: (event.clientY - box.top - state.ty) / state.k };
      ends = ends.length === 1 ? [ends[0], point] : [point];
      result = null;
      if (ends.length === 1) {
        say('Click the goal.');
      } else {
        const planned = plan(view.run);
        if (planned.why) {
          say(planned.why);
        } else {
          result = planned;
          say('Route: ' + planned.metres.toFixed(2) + ' m, ' + planned.bends +
            ' bends. Click a new start, or stop planning.');
        }
      }
      draw();
      return true;
    },
    // Draws the route again in views made afresh.
    redraw: draw,
  };
}
