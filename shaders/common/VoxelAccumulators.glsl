// The voxelizer's running sums live in one r32f atlas of 2 x 2 x 3 grid-sized slots, so every GPU with the
// minimum of eight image units can bind them (one image instead of ten).
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

ivec3 accumulatorCoord(ivec3 voxel, int slot, int resolution)
{
    return voxel + resolution * ivec3(slot % 2, (slot / 2) % 2, slot / 4);
}
