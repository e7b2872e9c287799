// The voxelizer's running sums live in one r32f atlas, so every GPU with the minimum of eight image units can
// bind them (one image instead of ten). A voxel's twelve slots are a 4 x 3 block of texels (the atlas is
// 4n x 3n x n): the atomics of one fragment then touch three rows next to each other, not ten grids apart,
// which voxelizes faster.
#define ACC_ALBEDO_R 0
#define ACC_ALBEDO_G 1
#define ACC_ALBEDO_B 2
#define ACC_COUNT 3
#define ACC_NORMAL_X 4
#define ACC_NORMAL_Y 5
#define ACC_NORMAL_Z 6
#define ACC_EMISSION_R 7
#define ACC_EMISSION_G 8
#define ACC_EMISSION_B 9
#define ACC_SLOTS 10

ivec3 accumulatorCoord(ivec3 voxel, int slot, int resolution)
{
    return ivec3(voxel.x * 4 + (slot & 3), voxel.y * 3 + (slot >> 2), voxel.z);
}
