// Ken Perlin's permutation in private memory as pairs, for perlin3 and simplex3: entry i holds
// perm(i) in bits 0..7 and perm(i + 1) in bits 8..15, so one read serves both lookups their
// hashing makes at i and i + 1 (the values, so every result bit, are those of noisePerm;
// tests/codegen checks them against voxc::perlinPermutation). Why: llvmpipe reads a storage
// buffer lane by lane behind branches but a private array with one gather, and the permutation
// reads are most of a perlin3 or a simplex3. The table is a global with a constant initializer,
// i.e. stored from constants once per invocation at the top of main; filled from the noise-table
// buffer instead, each entry cost a lane-by-lane buffer read and a lane-by-lane store. It is not
// a `const` array: llvmpipe materialises a dynamically indexed constant array at every use.
int noisePermutationPairs[256] = int[256](
    41111, 35232, 23433, 23131, 3930, 33551, 3459, 51469, 24521, 24671, 13664, 49717, 59842, 2025, 57607, 36065,
    9356, 26404, 7783, 17694, 36421, 2190, 25352, 9571, 61477, 5616, 2581, 5898, 48663, 1726, 37894, 63380,
    30967, 60024, 19434, 75, 6656, 50458, 16069, 24126, 64606, 56316, 52187, 30155, 9077, 2851, 8203, 14624,
    45369, 8625, 22561, 60760, 38381, 14485, 22328, 44631, 5294, 32020, 34941, 43912, 43179, 17576, 44868, 19119,
    42314, 18341, 34375, 35718, 12427, 6960, 42523, 19878, 37453, 40594, 59294, 21479, 28499, 58735, 31461, 15482,
    54076, 34259, 59013, 56550, 27100, 23657, 10588, 14121, 11831, 62766, 10485, 62504, 26356, 36710, 13967, 16694,
    6465, 16153, 41279, 417, 55297, 20696, 18768, 53577, 19665, 33868, 48004, 53435, 22992, 4697, 43282, 51369,
    50376, 34756, 33415, 29826, 48244, 40892, 22175, 42070, 25764, 28004, 50797, 44486, 47789, 954, 16387, 13376,
    55604, 58073, 64226, 31994, 31612, 1403, 51717, 9930, 37670, 30355, 32374, 65406, 21247, 21842, 54357, 53204,
    52943, 15310, 58171, 12259, 4143, 14864, 4410, 46609, 48566, 7357, 10780, 57130, 47071, 43703, 54698, 30677,
    63607, 39160, 664, 11266, 39468, 41882, 18083, 56646, 39389, 26009, 39781, 42907, 11175, 44075, 2476, 33033,
    5761, 10006, 64807, 5117, 25107, 27746, 28268, 20334, 29007, 57457, 59616, 45800, 47538, 28857, 26736, 55912,
    63194, 25078, 58465, 64484, 8955, 61986, 49650, 61121, 53998, 37074, 3216, 48908, 46015, 41651, 61858, 20977,
    13137, 37171, 60305, 63979, 3833, 61198, 27631, 12651, 49201, 54976, 8150, 46367, 51125, 27335, 40298, 47261,
    21688, 52308, 45260, 29616, 31091, 12921, 11570, 32557, 1151, 38404, 65174, 35582, 60554, 52716, 24013, 56925,
    29406, 17266, 7491, 6173, 18456, 62280, 36339, 32909, 50048, 20163, 16974, 55106, 15831, 39997, 46236, 38836);

// (perm(i), perm(i + 1)).
ivec2 noisePermPair(int i) {
    int pair = noisePermutationPairs[i & 255];
    return ivec2(pair & 255, pair >> 8);
}
