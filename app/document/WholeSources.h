#pragma once

#include "NodeTransform.h"

#include <vector>

namespace vct::doc {

/**
 * What a project that lists no nodes and materials says about the nodes its sources give: each source's
 * optional "placement" (translation, rotation_deg, scale, dynamic), applied to every node made from it, so a
 * small project can put a model somewhere and make it dynamic (the bunny on the Sponza's floor).
 */
struct WholeSources {
    bool used = false; ///< the project omitted nodes and materials
    std::vector<NodeTransform> placement; ///< per source
    std::vector<bool> dynamic; ///< per source
};

} // namespace vct::doc
