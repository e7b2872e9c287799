#include "core/ResourceTable.h"

#include <algorithm>
#include <stdexcept>

namespace vct::render {

bool ResourceTable::apply(const std::string& owner, const std::vector<TextureSlot>& slots)
{
    bool lost = false;
    for (const TextureSlot& slot : slots) {
        auto entry = std::find_if(
            m_entries.begin(), m_entries.end(), [&](const Entry& e) { return e.name == slot.name; });
        if (entry == m_entries.end()) {
            m_entries.push_back({ slot.name, owner, slot.group, slot.texture });
        } else if (entry->owner != owner || entry->texture != slot.texture) {
            throw std::logic_error(
                "texture '" + std::string(slot.name) + "' is made by " + entry->owner + " and by " + owner);
        }
        gl::Texture& texture = *slot.texture;
        if (slot.desc == texture.desc() && bool(texture) == bool(slot.desc))
            continue;
        // Freeing loses nothing the owner still needs; a texture made anew holds nothing, unless zero is
        // what it should hold and there was nothing before.
        if (slot.desc && (texture || !slot.desc.zeroed))
            lost = true;
        texture = gl::Texture::create(slot.desc);
    }
    return lost;
}

const gl::Texture* ResourceTable::find(std::string_view name) const
{
    for (const Entry& e : m_entries)
        if (e.name == name)
            return e.texture;
    return nullptr;
}

std::uint64_t ResourceTable::byteSize(ResourceGroup group) const
{
    std::uint64_t total = 0;
    for (const Entry& e : m_entries)
        if (e.group == group && *e.texture)
            total += e.texture->desc().byteSize();
    return total;
}

} // namespace vct::render
