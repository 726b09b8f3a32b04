#include "spirv_layout.hpp"

#include "arealight/spirv_instructions.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <utility>

namespace arealight {
namespace {

// SPIR-V spec 3.42 opcodes, 3.7 storage classes, 3.20 decorations, 3.8 dimensions.
enum : uint32_t {
    kOpEntryPoint = 15,
    kOpTypeBool = 20,
    kOpTypeInt = 21,
    kOpTypeFloat = 22,
    kOpTypeVector = 23,
    kOpTypeMatrix = 24,
    kOpTypeImage = 25,
    kOpTypeSampler = 26,
    kOpTypeSampledImage = 27,
    kOpTypeArray = 28,
    kOpTypeRuntimeArray = 29,
    kOpTypeStruct = 30,
    kOpTypePointer = 32,
    kOpConstant = 43,
    kOpSpecConstant = 50,
    kOpVariable = 59,
    kOpDecorate = 71,
    kOpMemberDecorate = 72,
    kOpTypeAccelerationStructure = 5341,
};
enum : uint32_t { kUniformConstant = 0, kUniform = 2, kPushConstant = 9, kStorageBuffer = 12 };
enum : uint32_t {
    kBufferBlock = 3,
    kArrayStride = 6,
    kMatrixStride = 7,
    kBinding = 33,
    kDescriptorSet = 34,
    kOffset = 35
};
enum : uint32_t { kDimBuffer = 5, kDimSubpassData = 6, kGLCompute = 5, kSampledStorage = 2 };

constexpr uint32_t kMagic = 0x07230203;

// One pass over the module: each result id's defining instruction and the
// decorations the layout needs.
class Module {
  public:
    explicit Module(const std::vector<uint32_t>& w) : w_(w) {}

    bool scan(const std::string& entry, std::string& why) {
        if (w_.size() < kSpirvHeaderWords || w_[0] != kMagic) {
            why = "not a SPIR-V module (no magic number)";
            return false;
        }
        bool found = false;
        const std::size_t stop = for_each_spirv_instruction(w_, [&](std::size_t at, uint32_t n,
                                                                   uint32_t op) {
            const uint32_t* in = &w_[at];
            if (op == kOpEntryPoint && n >= 4 && in[1] == kGLCompute)
                found = found || literal(in + 3, n - 3) == entry;
            else if (op == kOpDecorate && n >= 3)
                decorate(in[1], in[2], n >= 4 ? in[3] : 0);
            else if (op == kOpMemberDecorate && n >= 5 &&
                     (in[3] == kOffset || in[3] == kMatrixStride))
                (in[3] == kOffset ? offset_ : matrix_stride_)[{in[1], in[2]}] = in[4];
            else if ((op >= kOpTypeBool && op <= kOpTypePointer) ||
                     op == kOpTypeAccelerationStructure)
                def_[in[1]] = {op, at};
            else if ((op == kOpConstant || op == kOpSpecConstant || op == kOpVariable) && n >= 4)
                def_[in[2]] = {op, at};
            if (op == kOpVariable && n >= 4) variables_.push_back(at);
        });
        if (stop != w_.size()) {
            why = "malformed instruction at word " + std::to_string(stop);
            return false;
        }
        if (!found) why = "no GLCompute entry point named '" + entry + "'";
        return found;
    }

    uint32_t op(uint32_t id) const {
        auto it = def_.find(id);
        return it == def_.end() ? 0 : it->second.first;
    }
    // Word k of id's defining instruction (0: none).
    uint32_t word(uint32_t id, std::size_t k) const {
        auto it = def_.find(id);
        if (it == def_.end()) return 0;
        const std::size_t at = it->second.second;
        return k < (w_[at] >> 16) ? w_[at + k] : 0;
    }
    std::size_t words(uint32_t id) const {
        auto it = def_.find(id);
        return it == def_.end() ? 0 : w_[it->second.second] >> 16;
    }
    // A 32-bit constant's value; 1 when it is not one (an unknown length counts once).
    uint32_t constant(uint32_t id) const {
        const uint32_t o = op(id);
        return (o == kOpConstant || o == kOpSpecConstant) ? word(id, 3) : 1;
    }

    // Bytes a value of the type spans in a block, with the member's matrix stride.
    uint32_t size_of(uint32_t type, uint32_t matrix_stride = 0, int depth = 0) const {
        if (depth > 32) return 0;  // a cycle in a malformed module
        switch (op(type)) {
            case kOpTypeBool:
                return 4;
            case kOpTypeInt:
            case kOpTypeFloat:
                return word(type, 2) / 8;
            case kOpTypeVector:
                return word(type, 3) * size_of(word(type, 2), 0, depth + 1);
            case kOpTypeMatrix:
                return word(type, 3) *
                       (matrix_stride ? matrix_stride : size_of(word(type, 2), 0, depth + 1));
            case kOpTypeArray: {
                auto s = array_stride_.find(type);
                const uint32_t stride = s != array_stride_.end()
                                            ? s->second
                                            : size_of(word(type, 2), matrix_stride, depth + 1);
                return constant(word(type, 3)) * stride;
            }
            case kOpTypeStruct: {
                uint32_t end = 0;
                for (uint32_t m = 0; m + 2 < words(type); ++m) {
                    auto o = offset_.find({type, m});
                    auto ms = matrix_stride_.find({type, m});
                    const uint32_t member = size_of(
                        word(type, 2 + m), ms == matrix_stride_.end() ? 0 : ms->second, depth + 1);
                    end = std::max(end, (o == offset_.end() ? 0 : o->second) + member);
                }
                return end;
            }
            default:
                return 0;
        }
    }

    std::optional<VkDescriptorType> descriptor_type(uint32_t storage, uint32_t type) const {
        if (storage == kStorageBuffer) return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        if (storage == kUniform)
            return buffer_block_.count(type) ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                                             : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        if (storage != kUniformConstant) return std::nullopt;
        switch (op(type)) {
            case kOpTypeImage: {
                const uint32_t dim = word(type, 3);
                const bool storage_image = word(type, 7) == kSampledStorage;
                if (dim == kDimSubpassData) return VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
                if (dim == kDimBuffer)
                    return storage_image ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                                         : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
                return storage_image ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                                     : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
            }
            case kOpTypeSampler:
                return VK_DESCRIPTOR_TYPE_SAMPLER;
            case kOpTypeSampledImage:
                // A samplerBuffer is bound as a texel buffer.
                return word(word(type, 2), 3) == kDimBuffer
                           ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                           : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
            case kOpTypeAccelerationStructure:
                return VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
            default:
                return std::nullopt;
        }
    }

    const std::vector<uint32_t>& w_;
    std::vector<std::size_t> variables_;
    std::map<uint32_t, uint32_t> set_, binding_, array_stride_;
    std::map<uint32_t, bool> buffer_block_;

  private:
    static std::string literal(const uint32_t* p, std::size_t words) {
        std::string s(reinterpret_cast<const char*>(p), words * 4);
        return s.substr(0, s.find('\0'));
    }
    void decorate(uint32_t id, uint32_t decoration, uint32_t value) {
        if (decoration == kDescriptorSet) set_[id] = value;
        if (decoration == kBinding) binding_[id] = value;
        if (decoration == kArrayStride) array_stride_[id] = value;
        if (decoration == kBufferBlock) buffer_block_[id] = true;
    }

    std::map<uint32_t, std::pair<uint32_t, std::size_t>> def_;  // id -> opcode, word index
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> offset_, matrix_stride_;
};

}  // namespace

std::optional<SpirvLayout> reflect_spirv_layout(const std::vector<uint32_t>& spirv,
                                                const std::string& entry, std::string& why) {
    Module m(spirv);
    if (!m.scan(entry, why)) return std::nullopt;
    SpirvLayout layout;
    std::map<std::pair<uint32_t, uint32_t>, SpirvDescriptor> slots;
    for (std::size_t at : m.variables_) {
        const uint32_t pointer = spirv[at + 1], id = spirv[at + 2], storage = spirv[at + 3];
        if (m.op(pointer) != kOpTypePointer) continue;
        uint32_t type = m.word(pointer, 3);
        if (storage == kPushConstant) {
            layout.push_constant_bytes = std::max(layout.push_constant_bytes, m.size_of(type));
            continue;
        }
        if (!m.set_.count(id) || !m.binding_.count(id)) continue;
        uint32_t count = 1;
        for (int depth = 0; depth < 8; ++depth) {
            if (m.op(type) == kOpTypeArray)
                count *= m.constant(m.word(type, 3));
            else if (m.op(type) != kOpTypeRuntimeArray)
                break;
            type = m.word(type, 2);
        }
        const auto kind = m.descriptor_type(storage, type);
        if (!kind) continue;
        const std::pair<uint32_t, uint32_t> key{m.set_.at(id), m.binding_.at(id)};
        // Aliased variables share a binding: the first declaration sets it.
        slots.emplace(key, SpirvDescriptor{key.first, key.second, *kind, std::max(count, 1u)});
    }
    for (auto& [key, d] : slots) layout.descriptors.push_back(d);
    return layout;
}

}  // namespace arealight
