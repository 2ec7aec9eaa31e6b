// The type check's stand-in for @recast-navigation/wasm's declarations
// (tsconfig.json `paths`; the bundler resolves the real package): that
// file declares its namespace as `declare module Recast`, which
// TypeScript 7 refuses (TS1540), and the project checks every library's
// declarations (skipLibCheck false). @recast-navigation/core's own types
// use these names only as opaque handles; the peers code never touches
// them.
declare function Recast<T>(target?: T): Promise<T & typeof Recast>;
declare namespace Recast {
  class BoolRef { private readonly recast: "BoolRef"; }
  class ChunkyTriMeshUtils { private readonly recast: "ChunkyTriMeshUtils"; }
  class CrowdUtils { private readonly recast: "CrowdUtils"; }
  class Detour { private readonly recast: "Detour"; }
  class DetourDebugDraw { private readonly recast: "DetourDebugDraw"; }
  class DetourNavMeshBuilder { private readonly recast: "DetourNavMeshBuilder"; }
  class DetourTileCacheBuilder { private readonly recast: "DetourTileCacheBuilder"; }
  class FloatArray { private readonly recast: "FloatArray"; }
  class FloatRef { private readonly recast: "FloatRef"; }
  class IntArray { private readonly recast: "IntArray"; }
  class IntRef { private readonly recast: "IntRef"; }
  class NavMesh { private readonly recast: "NavMesh"; }
  class NavMeshCalcTileLocResult { private readonly recast: "NavMeshCalcTileLocResult"; }
  class NavMeshExporter { private readonly recast: "NavMeshExporter"; }
  class NavMeshGetTilesAtResult { private readonly recast: "NavMeshGetTilesAtResult"; }
  class NavMeshImporter { private readonly recast: "NavMeshImporter"; }
  class NavMeshQuery { private readonly recast: "NavMeshQuery"; }
  class NavMeshRemoveTileResult { private readonly recast: "NavMeshRemoveTileResult"; }
  class NavMeshStoreTileStateResult { private readonly recast: "NavMeshStoreTileStateResult"; }
  class Recast { private readonly recast: "Recast"; }
  class RecastBuildContext { private readonly recast: "RecastBuildContext"; }
  class RecastCalcBoundsResult { private readonly recast: "RecastCalcBoundsResult"; }
  class RecastCalcGridSizeResult { private readonly recast: "RecastCalcGridSizeResult"; }
  class RecastDebugDraw { private readonly recast: "RecastDebugDraw"; }
  class RecastFastLZCompressor { private readonly recast: "RecastFastLZCompressor"; }
  class RecastLinearAllocator { private readonly recast: "RecastLinearAllocator"; }
  class TileCache { private readonly recast: "TileCache"; }
  class TileCacheAddTileResult { private readonly recast: "TileCacheAddTileResult"; }
  class TileCacheMeshProcess { private readonly recast: "TileCacheMeshProcess"; }
  class UnsignedCharArray { private readonly recast: "UnsignedCharArray"; }
  class UnsignedCharRef { private readonly recast: "UnsignedCharRef"; }
  class UnsignedIntArray { private readonly recast: "UnsignedIntArray"; }
  class UnsignedIntRef { private readonly recast: "UnsignedIntRef"; }
  class UnsignedShortArray { private readonly recast: "UnsignedShortArray"; }
  class UnsignedShortRef { private readonly recast: "UnsignedShortRef"; }
  class Vec3 { private readonly recast: "Vec3"; }
  class dtBVNode { private readonly recast: "dtBVNode"; }
  class dtCompressedTileRef { private readonly recast: "dtCompressedTileRef"; }
  class dtCrowd { private readonly recast: "dtCrowd"; }
  class dtCrowdAgent { private readonly recast: "dtCrowdAgent"; }
  class dtLink { private readonly recast: "dtLink"; }
  class dtMeshHeader { private readonly recast: "dtMeshHeader"; }
  class dtMeshTile { private readonly recast: "dtMeshTile"; }
  class dtNavMeshCreateParams { private readonly recast: "dtNavMeshCreateParams"; }
  class dtNavMeshParams { private readonly recast: "dtNavMeshParams"; }
  class dtObstacleRef { private readonly recast: "dtObstacleRef"; }
  class dtOffMeshConnection { private readonly recast: "dtOffMeshConnection"; }
  class dtPoly { private readonly recast: "dtPoly"; }
  class dtPolyDetail { private readonly recast: "dtPolyDetail"; }
  class dtQueryFilter { private readonly recast: "dtQueryFilter"; }
  class dtTileCacheLayerHeader { private readonly recast: "dtTileCacheLayerHeader"; }
  class dtTileCacheParams { private readonly recast: "dtTileCacheParams"; }
  class rcChunkyTriMesh { private readonly recast: "rcChunkyTriMesh"; }
  class rcChunkyTriMeshNode { private readonly recast: "rcChunkyTriMeshNode"; }
  class rcCompactCell { private readonly recast: "rcCompactCell"; }
  class rcCompactHeightfield { private readonly recast: "rcCompactHeightfield"; }
  class rcCompactSpan { private readonly recast: "rcCompactSpan"; }
  class rcConfig { private readonly recast: "rcConfig"; }
  class rcContext { private readonly recast: "rcContext"; }
  class rcContour { private readonly recast: "rcContour"; }
  class rcContourSet { private readonly recast: "rcContourSet"; }
  class rcHeightfield { private readonly recast: "rcHeightfield"; }
  class rcHeightfieldLayer { private readonly recast: "rcHeightfieldLayer"; }
  class rcHeightfieldLayerSet { private readonly recast: "rcHeightfieldLayerSet"; }
  class rcPolyMesh { private readonly recast: "rcPolyMesh"; }
  class rcPolyMeshDetail { private readonly recast: "rcPolyMeshDetail"; }
  class rcSpan { private readonly recast: "rcSpan"; }
  class rcSpanPool { private readonly recast: "rcSpanPool"; }
}
export default Recast;
