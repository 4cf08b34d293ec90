// Frames of a scene through the inverse-parameter array co-simulation (ip_cosim.hpp).
#include "ip_cosim.hpp"

namespace cig::cosim {
namespace {

template <int W>
class IpFrameCosimImpl final : public IpFrameCosim {
 public:
  explicit IpFrameCosimImpl(IpRtl& rtl)
      : lattice_{rtl.n_pp(), 0}, cosim_(rtl, hls::Word<W>(invparam_eps_code(lattice_.size()))) {}
  IpFrameResult run(const ScreenFrame& frame, const invparam::ArrayPacing& pacing) override {
    const InvparamSetup<W> setup = invparam_setup<W>(frame, lattice_);
    const invparam::InvparamScene<W> scene = invparam::scene_of_setup(setup);
    const int columns = lattice_.size();
    IpFrameResult r = cosim_.run_frame(stream(scene), columns, pacing);
    r.faces = std::int64_t(scene.faces.size());
    return r;
  }
  std::int64_t model_cycles(const ScreenFrame& frame, const invparam::ArrayPacing& pacing) const override {
    const InvparamSetup<W> setup = invparam_setup<W>(frame, lattice_);
    return cosim_.model_cycles(stream(invparam::scene_of_setup(setup)), lattice_.size(), pacing);
  }

 private:
  std::vector<invparam::StreamCode<W>> stream(const invparam::InvparamScene<W>& scene) const {
    return invparam::build_frame_stream(scene, lattice_.size(), cosim_.n_pp(), invparam::StreamMode::kFull);
  }
  InvparamLattice lattice_;  // L = N_PP (raster N_PP, one sample a pixel): setup_eps is -(L + 1)
  IpCosim<W> cosim_;
};

}  // namespace

std::unique_ptr<IpFrameCosim> make_ip_frame_cosim(IpRtl& rtl) {
  if (rtl.w() == 64) return std::make_unique<IpFrameCosimImpl<64>>(rtl);
  if (rtl.w() == 57) return std::make_unique<IpFrameCosimImpl<57>>(rtl);
  throw std::logic_error("ip cosim: no harness for W=" + std::to_string(rtl.w()));
}

}  // namespace cig::cosim
