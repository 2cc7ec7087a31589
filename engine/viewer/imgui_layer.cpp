#include "viewer/imgui_layer.h"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/vk_check.h"

namespace throng::render {
namespace {

void checkImGuiVk(VkResult result) {
  if (result != VK_SUCCESS) gpu::checkVk(result, "ImGui Vulkan backend", __FILE__, __LINE__);
}

// The backend is built without prototypes (volk owns the vk* symbols): hand it the loader.
PFN_vkVoidFunction loadVulkanFunction(const char* name, void* instance) {
  return vkGetInstanceProcAddr(static_cast<VkInstance>(instance), name);
}

gpu::Handle<VkRenderPass> makeOverlayPass(VkDevice device, VkFormat format) {
  VkAttachmentDescription color{};
  color.format = format;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the crowd is already in the image
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &reference;
  // The crowd's colour writes come before the panel's blended writes.
  VkSubpassDependency dependency{};
  dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
  dependency.dstSubpass = 0;
  dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependency.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependency.dstAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &color;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &dependency;
  VkRenderPass pass = VK_NULL_HANDLE;
  VK_CHECK(vkCreateRenderPass(device, &info, nullptr, &pass));
  return gpu::Handle<VkRenderPass>(
      pass, [device](VkRenderPass p) { vkDestroyRenderPass(device, p, nullptr); });
}

gpu::Handle<VkDescriptorPool> makeDescriptorPool(VkDevice device) {
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  info.maxSets = 8;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorPool(device, &info, nullptr, &pool));
  return gpu::Handle<VkDescriptorPool>(
      pool, [device](VkDescriptorPool p) { vkDestroyDescriptorPool(device, p, nullptr); });
}

}  // namespace

ImGuiLayer::ImGuiLayer(const gpu::Context& context, Window& window, const Swapchain& swapchain,
                       uint32_t framesInFlight)
    : context_(context), format_(swapchain.format()) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini dropped into the working directory
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 4.0f;

  VkDevice device = context.device();
  descriptorPool_ = makeDescriptorPool(device);
  renderPass_ = makeOverlayPass(device, format_);
  // Chains the window's own callbacks behind ImGui's (installed before this).
  backendsReady_[0] = ImGui_ImplGlfw_InitForVulkan(window.handle(), true);
  if (!backendsReady_[0]) fail("ImGui: the GLFW backend failed to start");
  if (!ImGui_ImplVulkan_LoadFunctions(loadVulkanFunction, context.instance()))
    fail("ImGui: cannot load the Vulkan functions its backend needs");

  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = context.instance();
  info.PhysicalDevice = context.physicalDevice();
  info.Device = device;
  info.QueueFamily = context.queueFamily();
  info.Queue = context.queue();
  info.DescriptorPool = descriptorPool_;
  info.MinImageCount = std::max(2u, swapchain.minImageCount());
  // The backend rotates its vertex buffers over ImageCount frames: more than can be in flight.
  info.ImageCount = std::max({info.MinImageCount, swapchain.imageCount(), framesInFlight + 1});
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = checkImGuiVk;
  backendsReady_[1] = ImGui_ImplVulkan_Init(&info, renderPass_);
  if (!backendsReady_[1]) fail("ImGui: the Vulkan backend failed to start");

  gpu::submitAndWait(context,
                     [](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImGuiLayer::~ImGuiLayer() {
  vkDeviceWaitIdle(context_.device());
  framebuffers_.clear();
  if (backendsReady_[1]) ImGui_ImplVulkan_Shutdown();
  if (backendsReady_[0]) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::rebuildFramebuffers(const Swapchain& swapchain) {
  if (swapchain.format() != format_)
    fail("the swapchain changed format (", format_, " → ", swapchain.format(),
         "); restart the viewer");
  framebuffers_.clear();
  VkDevice device = context_.device();
  for (uint32_t i = 0; i < swapchain.imageCount(); ++i) {
    VkImageView view = swapchain.view(i);
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = swapchain.extent().width;
    info.height = swapchain.extent().height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(device, &info, nullptr, &framebuffer));
    framebuffers_.emplace_back(
        framebuffer, [device](VkFramebuffer f) { vkDestroyFramebuffer(device, f, nullptr); });
  }
}

void ImGuiLayer::newFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  frameOpen_ = true;
}

void ImGuiLayer::discardFrame() {
  if (!frameOpen_) return;
  ImGui::EndFrame();
  frameOpen_ = false;
}

void ImGuiLayer::record(VkCommandBuffer cmd, const Swapchain& swapchain, uint32_t imageIndex,
                        uint64_t generation) {
  THRONG_CHECK(frameOpen_, "ImGuiLayer::record without newFrame");
  ImGui::Render();
  frameOpen_ = false;
  if (generation != generation_ || framebuffers_.size() != swapchain.imageCount()) {
    rebuildFramebuffers(swapchain);  // the presenter waited for the device before rebuilding
    generation_ = generation;
  }
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = renderPass_;
  begin.framebuffer = framebuffers_[imageIndex];
  begin.renderArea = {{0, 0}, swapchain.extent()};
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vkCmdEndRenderPass(cmd);
}

bool ImGuiLayer::wantsMouse() const {
  return ImGui::GetIO().WantCaptureMouse;
}
bool ImGuiLayer::wantsKeyboard() const {
  return ImGui::GetIO().WantCaptureKeyboard;
}

}  // namespace throng::render
