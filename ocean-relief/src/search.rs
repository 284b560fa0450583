//! The fast generator: for each apex cell, a branch-and-bound over a min-depth pyramid of the
//! candidate cells, which finds exactly the minimum [`crate::bound`] defines.
//!
//! Each pyramid node keeps, over its candidate cells (non-flat ones for relaxed cones), the
//! smallest depth `m` and the union of their gradient boxes. A node is skipped when
//!
//! - `m ≥ Smax(q)`: no cell in it is higher than the apex cell's deepest corner;
//! - its lower bound `max(dist(q, node)/(Smax(q) − m), 1/L_global)` is not below the best value
//!   found so far: every cell's `A` has a larger distance and a smaller denominator, and every
//!   `B` is at least `1/L_global`;
//! - (relaxed) the falling test fails for the node's box, gradient union and twist signs, which
//!   contain each cell's, or no cell whose gradient can point some way lies where a vector from
//!   the apex box points that way too ([`falling_reach`]: the node keeps, for each of the four
//!   signs of `∂S/∂x` and `∂S/∂y`, the outermost edge of the cells that can have it);
//! - (quadrant cones, [`crate::quad`]) no vector from the apex box into the node lies in the
//!   quadrant: no cell of it can be reached by a ray the cone serves. The clipped box of a node
//!   contains its cells' clipped boxes, so its distance and growth bound theirs as before.
//!
//! None of these skips can drop a cell whose value is below the current best (`bound`'s
//! floating-point note: the node bounds are evaluated with the same monotone operations), so the
//! result is the brute force's bit for bit. Children are visited nearest bound first, and the
//! previous apex's best cell seeds the bound (its value is a candidate's value, so the minimum is
//! unchanged). A node that can only lower the clearance or the near cap (its bound is not below
//! the best `c`) is set aside until the plain cone is known: when that is the cap, `D` and `E`
//! are the cap too (`cone.rs`) and those nodes are never searched, which on the treads of a
//! staircase is nearly all of them. In wrap mode the pyramid is tiled: copies at Chebyshev ring `r ≥ 1` lie at least
//! `(r − 1)·N` texels away, which bounds their values from below by `(r − 1)·N` (a depth
//! difference is at most 1), so the rings stop as soon as that reaches the best value.

use alloc::vec;
use alloc::vec::Vec;

use crate::bound::{
    Apex, Cell, ConeKind, Grid, candidate, distance, falling, falling_reach, floor_value,
};
use crate::map::Edge;

#[derive(Clone, Copy, Debug)]
struct Node {
    m: f32,
    gx: [f32; 2],
    gy: [f32; 2],
    /// Bit 0: some cell has a positive twist; bit 1: some has a negative one.
    twists: u8,
    /// In cell coordinates of the pyramid copy: the largest right edge of the cells whose
    /// `∂S/∂x` can be positive, the smallest left edge of those whose `∂S/∂x` can be negative,
    /// the same along `y` (`∓∞`: none); see [`falling_reach`].
    reach: [f32; 4],
}

const EMPTY: Node = Node {
    m: f32::INFINITY,
    gx: [f32::INFINITY, f32::NEG_INFINITY],
    gy: [f32::INFINITY, f32::NEG_INFINITY],
    twists: 0,
    reach: [
        f32::NEG_INFINITY,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::INFINITY,
    ],
};

impl Node {
    fn merge(a: Node, b: Node) -> Node {
        Node {
            m: a.m.min(b.m),
            gx: [a.gx[0].min(b.gx[0]), a.gx[1].max(b.gx[1])],
            gy: [a.gy[0].min(b.gy[0]), a.gy[1].max(b.gy[1])],
            twists: a.twists | b.twists,
            reach: [
                a.reach[0].max(b.reach[0]),
                a.reach[1].min(b.reach[1]),
                a.reach[2].max(b.reach[2]),
                a.reach[3].min(b.reach[3]),
            ],
        }
    }
}

/// Level `l` has `S_l²` nodes, `S_0` the cells per side and `S_{l+1} = ⌈S_l / 2⌉` up to one
/// node; node `(x, y)` of level `l` covers cells `[x·2ˡ, (x + 1)·2ˡ) × [y·2ˡ, (y + 1)·2ˡ)`, those
/// that exist. Every node that exists is the node a pyramid padded to a power of two would hold
/// there (padding merges as an empty node), with the same number of levels, without the padding:
/// a clamped map has `N + 1` cells a side, which a power of two would round up to `2N`, four
/// times the memory. Level 0 is not stored: its nodes are read from the grid's cells
/// ([`Pyramid::base`]), which saves a node (40 bytes) a cell.
pub(crate) struct Pyramid {
    /// Levels 1 and up: side and nodes.
    levels: Vec<(usize, Vec<Node>)>,
    kind: ConeKind,
}

impl Pyramid {
    pub fn new(grid: &Grid<'_>, kind: ConeKind) -> Self {
        let mut levels: Vec<(usize, Vec<Node>)> = Vec::new();
        let mut size = grid.nc;
        while size > 1 {
            let half = size.div_ceil(2);
            let mut next = vec![EMPTY; half * half];
            for y in 0..half {
                for x in 0..half {
                    let at = |dx: usize, dy: usize| {
                        let (cx, cy) = (2 * x + dx, 2 * y + dy);
                        if cx >= size || cy >= size {
                            EMPTY
                        } else if let Some((_, prev)) = levels.last() {
                            prev[cy * size + cx]
                        } else {
                            Self::base(&grid.cells[cy * size + cx], kind, cx, cy)
                        }
                    };
                    next[y * half + x] = Node::merge(
                        Node::merge(at(0, 0), at(1, 0)),
                        Node::merge(at(0, 1), at(1, 1)),
                    );
                }
            }
            levels.push((half, next));
            size = half;
        }
        Self { levels, kind }
    }

    /// The level-0 node of the cell at `(x, y)`: the cell itself, or nothing for a flat cell
    /// under relaxed cones (never a candidate).
    #[inline(always)]
    fn base(c: &Cell, kind: ConeKind, x: usize, y: usize) -> Node {
        if kind == ConeKind::Conservative || !c.flat {
            // Cell coordinates are below 2²⁴: exact in f32.
            let (x, y) = (x as f32, y as f32);
            let edge = |can: bool, at: f32, none: f32| if can { at } else { none };
            Node {
                m: c.m,
                gx: c.gx,
                gy: c.gy,
                twists: match c.twist {
                    1 => 1,
                    -1 => 2,
                    _ => 0,
                },
                reach: [
                    edge(c.gx[1] > 0.0, x + 1.0, f32::NEG_INFINITY),
                    edge(c.gx[0] < 0.0, x, f32::INFINITY),
                    edge(c.gy[1] > 0.0, y + 1.0, f32::NEG_INFINITY),
                    edge(c.gy[0] < 0.0, y, f32::INFINITY),
                ],
            }
        } else {
            EMPTY
        }
    }

    /// The top level's index.
    fn top(&self) -> u32 {
        self.levels.len() as u32
    }

    /// Node `(x, y)` of `level` (`x`, `y` inside the level), level 0 from the grid's cells.
    #[inline(always)]
    fn node(&self, grid: &Grid<'_>, level: u32, x: usize, y: usize) -> Node {
        match level {
            0 => Self::base(&grid.cells[y * grid.nc + x], self.kind, x, y),
            l => {
                let (size, nodes) = &self.levels[l as usize - 1];
                nodes[y * size + x]
            }
        }
    }

    /// Side of `level`.
    #[inline(always)]
    fn side(&self, grid: &Grid<'_>, level: u32) -> usize {
        match level {
            0 => grid.nc,
            l => self.levels[l as usize - 1].0,
        }
    }
}

/// Channels computed in one search: the plain cone `c` (texels per unit depth), the clearance
/// `D` (texels) of the far candidates and the cap `E` (texels per unit depth) of the near ones.
pub(crate) const CHANNELS: usize = 3;

/// Candidates closer than this (texels, cell to cell) are near: they bound `E`, the others `D`.
pub(crate) const NEAR_DISTANCE: f64 = 1.0;

#[derive(Clone, Copy, Debug)]
struct Entry {
    /// Distance from the apex box and `Smax(q) − m` of the node.
    dist: f64,
    depth: f64,
    level: u32,
    x: u32,
    y: u32,
}

/// Scratch space reused across apexes.
#[derive(Default)]
pub(crate) struct Scratch {
    stack: Vec<Entry>,
    /// Nodes left for the clearance and near cap, with the origin of their pyramid copy.
    deferred: Vec<(Entry, i64, i64)>,
}

/// The result for one apex cell: per channel, the value and the cell that attains it (a seed for
/// the next apex).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Best {
    pub value: [f64; CHANNELS],
    pub cell: [Option<(i64, i64)>; CHANNELS],
}

/// What one search needs besides the apex.
pub(crate) struct Search<'a> {
    pub grid: &'a Grid<'a>,
    pub pyramid: &'a Pyramid,
    pub kind: ConeKind,
    /// Cap of every channel, texels (per unit depth for `c`).
    pub cap: f64,
    /// Halvings of the parts that sharpen `c` (`crate::refine`).
    pub parts: u32,
}

impl Search<'_> {
    /// Whether a node (or cell) with this distance and depth can still lower some channel: its
    /// plain bound `max(dist/depth, 1/L_global)` is below the best `c` (or, when it may hold near
    /// cells, the best `E`), or its distance below the best `D`.
    #[inline(always)]
    fn open(&self, dist: f64, depth: f64, floor: f64, best: &Best) -> bool {
        let plain = (dist / depth).max(floor);
        plain < best.value[0] || self.open_near(dist, plain, best)
    }

    /// [`Search::open`] for the clearance and near cap alone.
    #[inline(always)]
    fn open_near(&self, dist: f64, plain: f64, best: &Best) -> bool {
        dist < best.value[1] || (dist < NEAR_DISTANCE && plain < best.value[2])
    }

    fn offer(&self, q: &Apex, ci: i64, cj: i64, k: usize, best: &mut Best) {
        if let Some(cand) = candidate(
            q,
            &self.grid.cells[k],
            ci,
            cj,
            self.kind,
            self.grid.lip_global,
        ) {
            let near = cand.dist < NEAR_DISTANCE;
            let mut plain = best.value[0];
            crate::refine::refine(
                self.grid,
                q,
                &self.grid.cells[k],
                ci,
                cj,
                self.kind,
                cand.value(),
                self.parts,
                &mut plain,
            );
            let v = [
                plain,
                if near { f64::INFINITY } else { cand.dist },
                if near { cand.value() } else { f64::INFINITY },
            ];
            for ((value, cell), v) in best.value.iter_mut().zip(&mut best.cell).zip(v) {
                if v < *value {
                    *value = v;
                    *cell = Some((ci, cj));
                }
            }
        }
    }

    /// `c`, `D` and `E` of apex cell `q`, each capped at `cap`.
    pub fn cell_cone(
        &self,
        q: &Apex,
        seeds: &[Option<(i64, i64)>; CHANNELS],
        scratch: &mut Scratch,
    ) -> Best {
        let grid = self.grid;
        let floor = floor_value(grid.lip_global);
        let mut best = Best {
            value: [self.cap; CHANNELS],
            cell: [None; CHANNELS],
        };
        for (c, seed) in seeds.iter().enumerate() {
            if let Some((ci, cj)) = *seed {
                if seeds[..c].contains(seed) {
                    continue;
                }
                if let Some(k) = grid.index(ci, cj) {
                    self.offer(q, ci, cj, k, &mut best);
                }
            }
        }
        // No cell anywhere is higher than the apex's deepest corner: nothing can be a candidate,
        // in any tile copy.
        let root = self.pyramid.node(grid, self.pyramid.top(), 0, 0);
        if f64::from(root.m) >= q.smax {
            return best;
        }
        scratch.deferred.clear();
        match grid.edge {
            Edge::Clamp => self.visit(q, floor, grid.origin, grid.origin, &mut best, scratch),
            Edge::Wrap => {
                let n = grid.n as i64;
                let mut r = 0i64;
                loop {
                    // Copies on ring r ≥ 1 are at least (r − 1)·N away with depth ≤ 1.
                    let gap = ((r - 1).max(0) * n) as f64;
                    if r >= 1 && !self.open(gap, 1.0, floor, &best) {
                        break;
                    }
                    for b in -r..=r {
                        for a in -r..=r {
                            if a.abs().max(b.abs()) == r {
                                self.visit(q, floor, a * n, b * n, &mut best, scratch);
                            }
                        }
                    }
                    r += 1;
                }
            }
        }
        if best.value[0] >= self.cap {
            // The tracer's cone max(c, min(D/h, E)) is c whatever D and E hold when c is the cap
            // (E never exceeds it), so they are the cap too, and the nodes left for them need no
            // visit: on a staircase that is most of a tread's search.
            best.value[1] = self.cap;
            best.value[2] = self.cap;
            best.cell[1] = None;
            best.cell[2] = None;
        } else {
            let mut deferred = core::mem::take(&mut scratch.deferred);
            for &(e, ox, oy) in &deferred {
                self.descend(q, floor, ox, oy, e, &mut best, &mut scratch.stack, None);
            }
            deferred.clear();
            scratch.deferred = deferred;
        }
        best
    }

    /// Depth-first search of one copy of the pyramid whose cell `(0, 0)` is at `(ox, oy)`;
    /// nodes that can only lower the clearance or the near cap go to `scratch.deferred`.
    fn visit(
        &self,
        q: &Apex,
        floor: f64,
        ox: i64,
        oy: i64,
        best: &mut Best,
        scratch: &mut Scratch,
    ) {
        let top = self.pyramid.top();
        let Some((dist, depth)) = self.measure(q, floor, ox, oy, top, 0, 0, best) else {
            return;
        };
        let root = Entry {
            dist,
            depth,
            level: top,
            x: 0,
            y: 0,
        };
        self.descend(
            q,
            floor,
            ox,
            oy,
            root,
            best,
            &mut scratch.stack,
            Some(&mut scratch.deferred),
        );
    }

    /// Distance and depth of node `(x, y)` of `level` in the copy at `(ox, oy)`, or `None` when
    /// it is skipped.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn measure(
        &self,
        q: &Apex,
        floor: f64,
        ox: i64,
        oy: i64,
        level: u32,
        x: u32,
        y: u32,
        best: &Best,
    ) -> Option<(f64, f64)> {
        let size = self.pyramid.side(self.grid, level);
        // Past the last node of its level: no cell there (x·2ˡ ≥ the cell count).
        if x as usize >= size || y as usize >= size {
            return None;
        }
        let node = self.pyramid.node(self.grid, level, x as usize, y as usize);
        if f64::from(node.m) >= q.smax {
            return None;
        }
        let nc = self.grid.nc as i64;
        let (x0, y0) = (i64::from(x) << level, i64::from(y) << level);
        let x1 = ((i64::from(x) + 1) << level).min(nc);
        let y1 = ((i64::from(y) + 1) << level).min(nc);
        let rect = [
            (ox + x0) as f64,
            (ox + x1) as f64,
            (oy + y0) as f64,
            (oy + y1) as f64,
        ];
        // No direction the cone serves reaches the node: none of its cells is a candidate.
        let w = q.vectors(rect)?;
        let dist = distance(w);
        let depth = q.smax - f64::from(node.m);
        if !self.open(dist, depth, floor, best) {
            return None;
        }
        if self.kind == ConeKind::Relaxed
            && !(falling(w, node.gx, node.gy, node.twists)
                && falling_reach(
                    q,
                    w,
                    [
                        ox as f64 + f64::from(node.reach[0]),
                        ox as f64 + f64::from(node.reach[1]),
                        oy as f64 + f64::from(node.reach[2]),
                        oy as f64 + f64::from(node.reach[3]),
                    ],
                    node.twists,
                ))
        {
            return None;
        }
        Some((dist, depth))
    }

    /// The depth-first search below `start`. With `deferred`, a node that can no longer lower
    /// the plain cone (its bound is not below the best `c`, which only decreases) but can still
    /// lower the clearance or the near cap is set aside there instead of being searched.
    #[allow(clippy::too_many_arguments)]
    fn descend(
        &self,
        q: &Apex,
        floor: f64,
        ox: i64,
        oy: i64,
        start: Entry,
        best: &mut Best,
        stack: &mut Vec<Entry>,
        mut deferred: Option<&mut Vec<(Entry, i64, i64)>>,
    ) {
        stack.clear();
        stack.push(start);
        while let Some(e) = stack.pop() {
            let plain = (e.dist / e.depth).max(floor);
            if plain >= best.value[0] {
                if !self.open_near(e.dist, plain, best) {
                    continue;
                }
                if let Some(d) = deferred.as_deref_mut() {
                    d.push((e, ox, oy));
                    continue;
                }
            }
            if e.level == 0 {
                let (ci, cj) = (ox + i64::from(e.x), oy + i64::from(e.y));
                self.offer(q, ci, cj, e.y as usize * self.grid.nc + e.x as usize, best);
                continue;
            }
            let l = e.level - 1;
            let mut kids: [(f64, Entry); 4] = [(0.0, e); 4];
            let mut count = 0;
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let (x, y) = (2 * e.x + dx, 2 * e.y + dy);
                if let Some((dist, depth)) = self.measure(q, floor, ox, oy, l, x, y, best) {
                    kids[count] = (
                        dist,
                        Entry {
                            dist,
                            depth,
                            level: l,
                            x,
                            y,
                        },
                    );
                    count += 1;
                }
            }
            let kids = &mut kids[..count];
            // Farthest pushed first so the nearest is popped first.
            kids.sort_unstable_by(|a, b| b.0.total_cmp(&a.0));
            stack.extend(kids.iter().map(|k| k.1));
        }
    }
}
