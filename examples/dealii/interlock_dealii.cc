// interlock in deal.II: a rough rock joint between two rock blocks in a p4est-distributed
// hexahedral mesh. The joint is a thin layer of hexahedral cells (thickness h); at each of the
// layer's quadrature points the interlock law (through its C API, batched over every point of
// the process) gives the traction and the consistent tangent from the separation
// s = h (eps_nn, 2 eps_nt1, 2 eps_nt2) in the frame (n = z, t1 = x, t2 = y). The other strain
// components of the layer are linear elastic (modulus e_other), the blocks isotropic elastic.
//
// Loading (a direct-shear machine): the bottom face is fixed; the top face is a rigid platen
// whose in-plane displacement is prescribed and whose normal displacement is one unknown
// carrying the normal force sigma_N A. Increment 1 applies sigma_N at zero slip, increments
// 2 .. n_slip + 1 slide the platen by slip / n_slip each along angle_deg from x.
//
// Newton with the law's consistent tangent; a direct solve (MUMPS through PETSc) or GMRES with
// BoomerAMG; an increment is cut back when a point fails or asks for a cut (its step fraction
// < 1 at the converged iterate). The quadrature-point state lives with the cells
// (CellDataStorage) and is packed with them for a checkpoint (Triangulation::save), so a
// restart on any number of processes continues the run. docs/dealii.md describes it all.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/utilities.h>

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_precondition.h>
#include <deal.II/lac/petsc_solver.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <interlock.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace interlock_dealii
{
  using namespace dealii;
  constexpr int dim = 3;

  // What a run does: key=value arguments on the command line (docs/dealii.md lists them).
  struct Settings
  {
    std::string  scene            = "shear";
    unsigned int n_xy             = 2;    // cells across the joint, each way
    unsigned int n_block          = 0;    // cell layers of each rock block (0: the joint only)
    unsigned int refine           = 0;    // global refinements of that mesh
    double       length           = 10.0; // side of the square joint [mm]
    double       layer            = 0.1;  // thickness h of the layer [mm]
    double       block            = 5.0;  // thickness of each block [mm]
    double       e_block          = 50000.0; // Young's modulus of the rock [MPa]
    double       nu_block         = 0.25;
    double       e_other          = 1.0;  // the layer's in-plane moduli [MPa]
    double       normal           = -1.5; // sigma_N [MPa]
    double       slip             = 2.0;  // platen slip [mm]
    double       angle_deg        = 45.0; // slip direction from x (t1) [deg]
    unsigned int n_slip           = 40;   // increments of slip
    bool         accuracy_cuts    = true; // the law's step-fraction requests (damage, angle)
    std::string  solver           = "mumps"; // mumps | gmres (BoomerAMG)
    std::string  output_dir       = ".";
    std::string  curve            = "curve.csv";
    unsigned int vtu_every        = 0;    // write VTU/PVTU every k increments (0: never)
    int          checkpoint_after = -1;   // save a checkpoint after increment k and stop
    bool         restart          = false; // continue from output_dir's checkpoint
    unsigned int max_iterations   = 25;
    unsigned int verbose          = 0;    // 1: every Newton iteration's residual and cut
    double       tolerance        = 1e-10; // residual / (|sigma_N| A)

    void
    parse(int argc, char **argv);
  };

  void
  Settings::parse(int argc, char **argv)
  {
    // A scene first sets its defaults; later arguments override them.
    std::map<std::string, std::string> given;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        const auto        eq  = arg.find('=');
        if (eq == std::string::npos)
          throw std::invalid_argument("argument '" + arg + "' is not key=value");
        given[arg.substr(0, eq)] = arg.substr(eq + 1);
      }
    if (given.count("scene"))
      scene = given["scene"];
    if (scene == "shear")
      {
        // The joint alone between rigid platens: every point of the layer has the platen's
        // separation, so the layer is interlock-history's point (tests/mpi/test_dealii.py).
        n_xy          = 2;
        n_block       = 0;
        accuracy_cuts = false;
      }
    else if (scene == "block")
      {
        // The joint between elastic rock blocks with free sides: a non-uniform joint. With
        // 4 x 4 cells the platen's dof is not locally relevant on every process at np 2 and 4.
        n_xy    = 4;
        n_block = 1;
        n_slip  = 20;
      }
    else
      throw std::invalid_argument("scene = '" + scene + "': admissible shear or block");
    const std::map<std::string, double *> reals = {
      {"length", &length},   {"layer", &layer},       {"block", &block},
      {"e_block", &e_block}, {"nu_block", &nu_block}, {"e_other", &e_other},
      {"normal", &normal},   {"slip", &slip},         {"angle_deg", &angle_deg},
      {"tolerance", &tolerance}};
    const std::map<std::string, unsigned int *> counts = {
      {"n_xy", &n_xy},           {"n_block", &n_block},     {"refine", &refine},
      {"n_slip", &n_slip},       {"vtu_every", &vtu_every}, {"max_iterations", &max_iterations},
      {"verbose", &verbose}};
    const std::map<std::string, bool *>        flags = {{"accuracy_cuts", &accuracy_cuts},
                                                        {"restart", &restart}};
    const std::map<std::string, std::string *> texts = {{"solver", &solver},
                                                        {"output_dir", &output_dir},
                                                        {"curve", &curve}};
    for (const auto &kv : given)
      {
        const std::string &k = kv.first, &v = kv.second;
        try
          {
            size_t used = v.size();
            if (k == "scene")
              continue;
            else if (reals.count(k))
              *reals.at(k) = std::stod(v, &used);
            else if (counts.count(k))
              *counts.at(k) = static_cast<unsigned int>(std::stoul(v, &used));
            else if (flags.count(k))
              *flags.at(k) = (std::stoi(v, &used) != 0);
            else if (texts.count(k))
              *texts.at(k) = v;
            else if (k == "checkpoint_after")
              checkpoint_after = std::stoi(v, &used);
            else
              throw std::invalid_argument("unknown setting '" + k + "'");
            if (used != v.size())
              throw std::invalid_argument("");
          }
        catch (const std::logic_error &e) // stod and friends: invalid_argument, out_of_range
          {
            if (std::string(e.what()).rfind("unknown setting", 0) == 0)
              throw;
            throw std::invalid_argument("setting " + k + " = '" + v + "' is not a valid value");
          }
      }
    if (solver != "mumps" && solver != "gmres")
      throw std::invalid_argument("solver = '" + solver + "': admissible mumps or gmres");
    if (n_xy == 0 || n_slip == 0 || !(layer > 0) || !(length > 0) || !(block > 0))
      throw std::invalid_argument("n_xy, n_slip, layer, length and block must be positive");
  }

  // The state of one quadrature point of the layer: the C API's state (the UMAT's STATEV,
  // then the separation and the traction) at the last accepted increment. The Newton
  // iterate's state lives in the batch (JointProblem::batch_new) until the increment is
  // accepted.
  struct PointState
  {
    std::vector<double> committed;
  };

  // The granite joint of the shipped 3D decks (inputs/granite_3d_*.nml): the azimuthal RIA
  // with 3 azimuths. Without accuracy cuts the step-fraction bounds are at their widest.
  std::unique_ptr<interlock_material, void (*)(interlock_material *)>
  granite_joint(const bool accuracy_cuts)
  {
    std::vector<const char *> names = {"sigma0_n", "sigma0_t", "gc", "eta", "mu",
                                       "h_n", "theta0_deg", "thetaf_deg", "zeta0",
                                       "ria", "n_azimuths"};
    std::vector<double> values = {0.025, 0.025, 0.0005, 0.99, 0.6898538,
                                  4.0, 30.0, 9.0, 6.666, 1.0, 3.0};
    if (!accuracy_cuts)
      {
        names.push_back("max_damage_increment");
        values.push_back(1.0);
        names.push_back("max_angle_increment_deg");
        values.push_back(90.0);
      }
    interlock_material *m = nullptr;
    char                message[512];
    if (interlock_material_from_names(dim, static_cast<int>(names.size()), names.data(),
                                      values.data(), &m, message, sizeof message) !=
        INTERLOCK_OK)
      throw std::runtime_error(std::string("interlock refuses the material: ") + message);
    return {m, interlock_material_free};
  }

  // Seconds spent in each part of the Newton iterations: wall clock, and the process's CPU
  // time (what a loaded machine does not inflate; it counts an MPI wait that spins).
  struct Cost
  {
    double       law = 0, assembly = 0, solve = 0;
    double       law_cpu = 0, assembly_cpu = 0, solve_cpu = 0;
    unsigned int iterations = 0;
  };

  inline double
  cpu_seconds()
  {
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  }

  class JointProblem
  {
  public:
    JointProblem(const Settings &settings);
    void
    run();

  private:
    using Clock = std::chrono::steady_clock;

    void
    make_grid();
    void
    setup_system();
    void
    initialise_state();
    void
    set_platen(const double t);
    bool
    assemble(Cost &cost, double &min_fraction);
    void
    solve(Cost &cost);
    bool
    newton(Cost &cost, unsigned int &iterations, double &min_fraction);
    void
    commit_state();
    std::string
    curve_row(const unsigned int increment, const double t, const unsigned int substeps,
              const unsigned int iterations);
    void
    write_vtu(const unsigned int increment);
    void
    save_checkpoint(const unsigned int increment, const double t);
    unsigned int
    load_checkpoint(double &t);

    double
    normal_factor(const double t) const
    {
      return std::min(t, 1.0);
    }
    double
    slip_at(const double t) const
    {
      return t <= 1.0 ? 0.0 : settings.slip * (t - 1.0) / settings.n_slip;
    }
    bool
    in_layer(const typename Triangulation<dim>::cell_iterator &cell) const
    {
      return cell->material_id() == layer_id;
    }

    Settings                                  settings;
    MPI_Comm                                  comm;
    ConditionalOStream                        pcout;
    parallel::distributed::Triangulation<dim> triangulation;
    FESystem<dim>                             fe;
    DoFHandler<dim>                           dof_handler;
    QGauss<dim>                               quadrature;
    QGauss<dim - 1>                           face_quadrature;
    std::unique_ptr<interlock_material, void (*)(interlock_material *)> material;
    unsigned int                              state_size;
    unsigned int                              statev_size;
    std::vector<unsigned int>                 damage_slots;

    IndexSet                          owned_dofs, relevant_dofs;
    AffineConstraints<double>         constraints; // homogeneous: Newton's corrections
    types::global_dof_index           platen_dof = 0; // the platen's normal displacement
    PETScWrappers::MPI::SparseMatrix  matrix;
    PETScWrappers::MPI::Vector        solution, ghosted, rhs;
    // The solution before the last accepted substep of the slip phase and that substep's
    // length: the predictor of the next substep (0: none).
    PETScWrappers::MPI::Vector        previous;
    double                            dt_previous = 0;

    CellDataStorage<typename Triangulation<dim>::cell_iterator, PointState> storage;

    // The batch of the process's layer points handed to interlock_update at once.
    std::vector<double> batch_separation, batch_old, batch_new, batch_traction, batch_tangent,
      batch_fraction;
    std::vector<int> batch_status;

    std::vector<std::string> curve_rows;
    double                   top_z          = 0;
    double                   current_normal = 0; // sigma_N of the increment's end [MPa]
    double                   force_scale    = 1; // |sigma_N| A: the residual's scale [N]

    static constexpr types::material_id  layer_id = 1;
    static constexpr types::boundary_id bottom_id = 4, top_id = 5; // colorize: z faces
  };

  JointProblem::JointProblem(const Settings &settings_)
    : settings(settings_)
    , comm(MPI_COMM_WORLD)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , triangulation(comm)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
    , quadrature(2)
    , face_quadrature(2)
    , material(granite_joint(settings.accuracy_cuts))
    , state_size(static_cast<unsigned int>(interlock_state_size(material.get())))
    , statev_size(static_cast<unsigned int>(interlock_statev_size(material.get())))
  {
    const int n = interlock_state_variable_count(material.get());
    for (int i = 0; i < n; ++i)
      {
        char   name[64], unit[16];
        int    plane = 0;
        double lo = 0, hi = 0;
        if (interlock_state_variable_info(material.get(), i, name, sizeof name, unit,
                                          sizeof unit, &plane, &lo, &hi) == INTERLOCK_OK &&
            std::strcmp(name, "damage") == 0)
          damage_slots.push_back(static_cast<unsigned int>(i));
      }
  }

  // The box [0, L]^2 x [-B, h + B]: n_block cell layers of rock below and above one cell
  // layer of joint [0, h] (material id 1). Boundary ids from colorize: 4 bottom, 5 top.
  void
  JointProblem::make_grid()
  {
    const double              L = settings.length, h = settings.layer, B = settings.block;
    std::vector<std::vector<double>> steps(dim);
    steps[0].assign(settings.n_xy, L / settings.n_xy);
    steps[1].assign(settings.n_xy, L / settings.n_xy);
    for (unsigned int i = 0; i < settings.n_block; ++i)
      steps[2].push_back(B / settings.n_block);
    steps[2].push_back(h);
    for (unsigned int i = 0; i < settings.n_block; ++i)
      steps[2].push_back(B / settings.n_block);
    const double bottom = settings.n_block > 0 ? -B : 0.0;
    top_z               = settings.n_block > 0 ? h + B : h;
    GridGenerator::subdivided_hyper_rectangle(triangulation, steps, Point<dim>(0, 0, bottom),
                                              Point<dim>(L, L, top_z), true);
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      {
        const double z = cell->center()[2];
        cell->set_material_id(z > 0 && z < h ? layer_id : 0);
      }
  }

  void
  JointProblem::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);

    // The platen's normal displacement: the smallest z dof of the top face, on every process.
    const FEValuesExtractors::Scalar     z_component(2);
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    std::vector<types::global_dof_index> top_z_dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == top_id)
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                if (fe.face_system_to_component_index(i).first == 2)
                  top_z_dofs.push_back(face_dofs[i]);
            }
    types::global_dof_index local_min = std::numeric_limits<types::global_dof_index>::max();
    for (const auto d : top_z_dofs)
      local_min = std::min(local_min, d);
    platen_dof = Utilities::MPI::min(local_min, comm);

    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(dof_handler, bottom_id,
                                             Functions::ZeroFunction<dim>(dim), constraints);
    VectorTools::interpolate_boundary_values(dof_handler, top_id,
                                             Functions::ZeroFunction<dim>(dim), constraints,
                                             ComponentMask({true, true, false}));
    for (const auto d : top_z_dofs)
      if (d != platen_dof && !constraints.is_constrained(d))
        {
          constraints.add_line(d);
          constraints.add_entry(d, platen_dof, 1.0);
        }
    constraints.close();

    // The platen's row couples to every top-face dof of every process (the ties condense into
    // it): each process keeps its share of that row, even where the platen's dof is not
    // locally relevant, and hands it to the owner.
    IndexSet rows = relevant_dofs;
    rows.add_index(platen_dof);
    DynamicSparsityPattern dsp(rows);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned_dofs, comm, rows);
    matrix.reinit(owned_dofs, owned_dofs, dsp, comm);
    solution.reinit(owned_dofs, comm);
    previous.reinit(owned_dofs, comm);
    rhs.reinit(owned_dofs, comm);
    ghosted.reinit(owned_dofs, relevant_dofs, comm);
  }

  // Virgin state at every quadrature point of the process's layer cells.
  void
  JointProblem::initialise_state()
  {
    const unsigned int nq = quadrature.size();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        {
          storage.initialize(cell, nq);
          for (auto &p : storage.get_data(cell))
            {
              p->committed.resize(state_size);
              if (interlock_state_init(material.get(), 0, 1, p->committed.data()) !=
                  INTERLOCK_OK)
                throw std::runtime_error("interlock_state_init failed");
            }
        }
  }

  // The platen at time t: its in-plane displacement into the solution (bottom face 0).
  void
  JointProblem::set_platen(const double t)
  {
    const double a = settings.angle_deg * numbers::PI / 180.0, u = slip_at(t);
    std::map<types::global_dof_index, double> values;
    VectorTools::interpolate_boundary_values(dof_handler, bottom_id,
                                             Functions::ZeroFunction<dim>(dim), values);
    VectorTools::interpolate_boundary_values(
      dof_handler, top_id,
      Functions::ConstantFunction<dim>(std::vector<double>{u * std::cos(a), u * std::sin(a), 0.0}),
      values, ComponentMask({true, true, false}));
    for (const auto &kv : values)
      if (owned_dofs.is_element(kv.first))
        solution(kv.first) = kv.second;
    solution.compress(VectorOperation::insert);
  }

  // Voigt order (xx, yy, zz, yz, xz, xy) with engineering shears.
  using Voigt = std::array<double, 6>;
  inline Voigt
  voigt(const SymmetricTensor<2, dim> &e)
  {
    return {{e[0][0], e[1][1], e[2][2], 2 * e[1][2], 2 * e[0][2], 2 * e[0][1]}};
  }

  // The residual and the tangent at the current iterate (ghosted). The law runs once on every
  // layer point of the process (one batched call); returns false when a point fails.
  bool
  JointProblem::assemble(Cost &cost, double &min_fraction)
  {
    const auto         t0 = Clock::now();
    const double       c0 = cpu_seconds();
    const unsigned int nq = quadrature.size(), nd = fe.n_dofs_per_cell();
    const double       h  = settings.layer;
    FEValues<dim>      fv(fe, quadrature, update_gradients | update_JxW_values);
    FEFaceValues<dim>  ffv(fe, face_quadrature, update_values | update_JxW_values);
    const FEValuesExtractors::Vector     u(0);
    std::vector<SymmetricTensor<2, dim>> strain(nq);
    std::vector<types::global_dof_index> dofs(nd);

    // 1. The layer's separations, gathered with the old states into the batch.
    size_t n = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        n += nq;
    batch_separation.resize(3 * n);
    batch_old.resize(state_size * n);
    batch_new.resize(state_size * n);
    batch_traction.resize(3 * n);
    batch_tangent.resize(9 * n);
    batch_status.resize(n);
    batch_fraction.resize(n);
    size_t p = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        {
          fv.reinit(cell);
          fv[u].get_function_symmetric_gradients(ghosted, strain);
          const auto data = storage.get_data(cell);
          for (unsigned int q = 0; q < nq; ++q, ++p)
            {
              batch_separation[3 * p + 0] = h * strain[q][2][2];
              batch_separation[3 * p + 1] = h * 2 * strain[q][0][2];
              batch_separation[3 * p + 2] = h * 2 * strain[q][1][2];
              std::copy(data[q]->committed.begin(), data[q]->committed.end(),
                        batch_old.begin() + state_size * p);
            }
        }
    const auto   t1 = Clock::now();
    const double c1 = cpu_seconds();
    // 2. The law.
    const size_t failed =
      interlock_update(material.get(), n, batch_separation.data(), batch_old.data(),
                       batch_new.data(), batch_traction.data(), batch_tangent.data(),
                       batch_status.data(), batch_fraction.data());
    const auto   t2 = Clock::now();
    const double c2 = cpu_seconds();
    cost.law_cpu += c2 - c1;
    min_fraction  = 1.0;
    for (size_t i = 0; i < n; ++i)
      min_fraction = std::min(min_fraction, batch_fraction[i]);
    min_fraction = Utilities::MPI::min(min_fraction, comm);
    const unsigned int any_failed =
      Utilities::MPI::max(static_cast<unsigned int>(failed > 0), comm);
    if (any_failed)
      {
        for (size_t i = 0; i < n; ++i)
          if (batch_status[i] != INTERLOCK_OK)
            {
              char message[512];
              interlock_update_message(material.get(), &batch_separation[3 * i],
                                       &batch_old[state_size * i], message, sizeof message);
              std::cout << "  process " << Utilities::MPI::this_mpi_process(comm)
                        << ": a layer point fails: " << message << std::endl;
              break;
            }
        cost.law += std::chrono::duration<double>(t2 - t1).count();
        cost.assembly += std::chrono::duration<double>(t1 - t0).count();
        cost.assembly_cpu += c1 - c0;
        return false;
      }

    // 3. Assembly.
    const double lambda = settings.e_block * settings.nu_block /
                          ((1 + settings.nu_block) * (1 - 2 * settings.nu_block));
    const double mu = settings.e_block / (2 * (1 + settings.nu_block));
    double       D_rock[6][6] = {};
    for (unsigned int i = 0; i < 3; ++i)
      {
        for (unsigned int j = 0; j < 3; ++j)
          D_rock[i][j] = lambda;
        D_rock[i][i] += 2 * mu;
        D_rock[i + 3][i + 3] = mu;
      }
    // The layer's law components in Voigt order: normal zz (2), t1 xz (4), t2 yz (3).
    const unsigned int law_slot[3] = {2, 4, 3};
    matrix = 0;
    rhs    = 0;
    FullMatrix<double>    cell_matrix(nd, nd);
    Vector<double>        cell_rhs(nd);
    std::vector<Voigt>    B(nd);
    double                D[6][6];
    Voigt                 stress;
    p = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_matrix = 0;
          cell_rhs    = 0;
          fv.reinit(cell);
          fv[u].get_function_symmetric_gradients(ghosted, strain);
          const bool layer = in_layer(cell);
          for (unsigned int q = 0; q < nq; ++q)
            {
              const Voigt e = voigt(strain[q]);
              if (layer)
                {
                  std::fill(&D[0][0], &D[0][0] + 36, 0.0);
                  D[0][0] = D[1][1] = D[5][5] = settings.e_other;
                  for (unsigned int a = 0; a < 3; ++a)
                    for (unsigned int b = 0; b < 3; ++b)
                      D[law_slot[a]][law_slot[b]] = h * batch_tangent[9 * p + 3 * a + b];
                  for (unsigned int i = 0; i < 6; ++i)
                    stress[i] = (i == 0 || i == 1 || i == 5) ? settings.e_other * e[i] : 0.0;
                  for (unsigned int a = 0; a < 3; ++a)
                    stress[law_slot[a]] = batch_traction[3 * p + a];
                  ++p;
                }
              else
                for (unsigned int i = 0; i < 6; ++i)
                  {
                    stress[i] = 0;
                    for (unsigned int j = 0; j < 6; ++j)
                      {
                        D[i][j] = D_rock[i][j];
                        stress[i] += D_rock[i][j] * e[j];
                      }
                  }
              const double w = fv.JxW(q);
              for (unsigned int i = 0; i < nd; ++i)
                B[i] = voigt(fv[u].symmetric_gradient(i, q));
              for (unsigned int i = 0; i < nd; ++i)
                {
                  Voigt DBi_T{}; // row i of B^T D
                  for (unsigned int k = 0; k < 6; ++k)
                    {
                      double s = 0;
                      for (unsigned int l = 0; l < 6; ++l)
                        s += B[i][l] * D[l][k];
                      DBi_T[k] = s;
                    }
                  double r = 0;
                  for (unsigned int k = 0; k < 6; ++k)
                    r += B[i][k] * stress[k];
                  cell_rhs(i) -= r * w;
                  for (unsigned int j = 0; j < nd; ++j)
                    {
                      double s = 0;
                      for (unsigned int k = 0; k < 6; ++k)
                        s += DBi_T[k] * B[j][k];
                      cell_matrix(i, j) += s * w;
                    }
                }
            }
          // The platen's normal force sigma_N A, as a traction on the top face (the ties
          // carry it to the platen's one unknown).
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == top_id)
              {
                ffv.reinit(cell, f);
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  for (unsigned int i = 0; i < nd; ++i)
                    if (fe.system_to_component_index(i).first == 2)
                      cell_rhs(i) += current_normal * ffv.shape_value(i, q) * ffv.JxW(q);
              }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, matrix, rhs);
        }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    const auto t3 = Clock::now();
    cost.assembly_cpu += (c1 - c0) + (cpu_seconds() - c2);
    cost.law += std::chrono::duration<double>(t2 - t1).count();
    cost.assembly += std::chrono::duration<double>((t1 - t0) + (t3 - t2)).count();
    return true;
  }

  // One Newton correction: K du = -r with the homogeneous constraints, then the ties and the
  // fixed components filled in.
  void
  JointProblem::solve(Cost &cost)
  {
    const auto                 t0 = Clock::now();
    const double               c0 = cpu_seconds();
    PETScWrappers::MPI::Vector du(owned_dofs, comm);
    if (settings.solver == "mumps")
      {
        SolverControl                    control(1, 0);
        PETScWrappers::SparseDirectMUMPS direct(control, comm);
        direct.solve(matrix, du, rhs);
      }
    else
      {
        // Inexact Newton: the correction to 1e-8 of the residual.
        SolverControl                 control(2000, 1e-8 * rhs.l2_norm());
        PETScWrappers::SolverGMRES    gmres(control, comm);
        PETScWrappers::PreconditionBoomerAMG amg(
          matrix, PETScWrappers::PreconditionBoomerAMG::AdditionalData());
        gmres.solve(matrix, du, rhs, amg);
      }
    constraints.distribute(du);
    solution += du;
    cost.solve += std::chrono::duration<double>(Clock::now() - t0).count();
    cost.solve_cpu += cpu_seconds() - c0;
  }

  // Newton on the increment whose end is already in the platen's values. False when a point
  // fails or the iterations do not converge; min_fraction is the smallest step fraction the
  // points ask for (at the converged iterate when true).
  bool
  JointProblem::newton(Cost &cost, unsigned int &iterations, double &min_fraction)
  {
    for (unsigned int it = 0;; ++it)
      {
        ghosted = solution;
        if (!assemble(cost, min_fraction))
          return false;
        const double r = rhs.l2_norm();
        if (settings.verbose > 0)
          pcout << "    iteration " << it << ": residual " << r / force_scale
                << ", smallest step fraction " << min_fraction << std::endl;
        if (!std::isfinite(r))
          return false;
        if (r <= settings.tolerance * force_scale)
          return true;
        if (it == settings.max_iterations)
          {
            min_fraction = 0.5;
            return false;
          }
        solve(cost);
        ++iterations;
        ++cost.iterations;
      }
  }

  // The converged iterate's states become the points' states.
  void
  JointProblem::commit_state()
  {
    size_t p = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        for (auto &d : storage.get_data(cell))
          {
            std::copy(batch_new.begin() + state_size * p,
                      batch_new.begin() + state_size * (p + 1), d->committed.begin());
            ++p;
          }
  }

  // One row of the curve: the platen's displacement, the layer's mean separation and traction
  // (area-weighted), mean damage and the largest departure of a point's traction from the mean.
  std::string
  JointProblem::curve_row(const unsigned int increment, const double t,
                          const unsigned int substeps, const unsigned int iterations)
  {
    FEValues<dim>      fv(fe, quadrature, update_JxW_values);
    const unsigned int nq = quadrature.size();
    std::vector<double> sums(8, 0.0); // area, sN, sT1, sT2, tN, tT1, tT2, damage
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        {
          fv.reinit(cell);
          const auto data = storage.get_data(cell);
          for (unsigned int q = 0; q < nq; ++q)
            {
              const double *s = data[q]->committed.data();
              const double  w = fv.JxW(q);
              sums[0] += w;
              for (unsigned int c = 0; c < 6; ++c)
                sums[1 + c] += w * s[statev_size + c];
              double d = 0;
              for (const auto k : damage_slots)
                d += s[k];
              sums[7] += w * d / std::max<size_t>(1, damage_slots.size());
            }
        }
    Utilities::MPI::sum(sums, comm, sums);
    std::array<double, 6> mean;
    for (unsigned int c = 0; c < 6; ++c)
      mean[c] = sums[1 + c] / sums[0];
    double spread = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        for (const auto &d : storage.get_data(cell))
          for (unsigned int c = 3; c < 6; ++c)
            spread = std::max(spread, std::abs(d->committed[statev_size + c] - mean[c]));
    spread = Utilities::MPI::max(spread, comm);
    double uz = owned_dofs.is_element(platen_dof) ? solution(platen_dof) : 0.0;
    uz        = Utilities::MPI::sum(uz, comm);
    const double       a = settings.angle_deg * numbers::PI / 180.0, u = slip_at(t);
    std::ostringstream row;
    row << increment << ',' << substeps << ',' << iterations << std::setprecision(17) << ','
        << t << ',' << u * std::cos(a) << ',' << u * std::sin(a) << ',' << uz;
    for (unsigned int c = 0; c < 6; ++c)
      row << ',' << mean[c];
    row << ',' << sums[7] / sums[0] << ',' << spread;
    return row.str();
  }

  const char *const curve_header =
    "increment,substeps,iterations,t,platen_ux,platen_uy,platen_uz,s_n,s_t1,s_t2,"
    "sigma_n,sigma_t1,sigma_t2,damage,traction_spread";

  // Displacement, and per cell of the layer its mean damage, slip |s_T| and dilation s_N.
  void
  JointProblem::write_vtu(const unsigned int increment)
  {
    ghosted = solution;
    Vector<float> damage(triangulation.n_active_cells()), slip(triangulation.n_active_cells()),
      dilation(triangulation.n_active_cells()), rank(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          rank(cell->active_cell_index()) = Utilities::MPI::this_mpi_process(comm);
          if (!in_layer(cell))
            continue;
          double     d = 0, s = 0, n = 0;
          const auto data = storage.get_data(cell);
          for (const auto &p : data)
            {
              const double *x = p->committed.data();
              for (const auto k : damage_slots)
                d += x[k] / damage_slots.size();
              s += std::hypot(x[statev_size + 1], x[statev_size + 2]);
              n += x[statev_size];
            }
          damage(cell->active_cell_index())   = d / data.size();
          slip(cell->active_cell_index())     = s / data.size();
          dilation(cell->active_cell_index()) = n / data.size();
        }
    DataOut<dim> out;
    out.attach_dof_handler(dof_handler);
    out.add_data_vector(ghosted, std::vector<std::string>(dim, "displacement"),
                        DataOut<dim>::type_dof_data,
                        std::vector<DataComponentInterpretation::DataComponentInterpretation>(
                          dim, DataComponentInterpretation::component_is_part_of_vector));
    out.add_data_vector(damage, "damage");
    out.add_data_vector(slip, "slip");
    out.add_data_vector(dilation, "dilation");
    out.add_data_vector(rank, "process");
    out.build_patches();
    out.write_vtu_with_pvtu_record(settings.output_dir + "/", "joint", increment, comm, 4);
  }

  // The distributed mesh, the solution and every layer point's state (packed with its cell,
  // so a restart on another number of processes finds each state with its cell), and the
  // increment, time and curve so far (checkpoint.txt).
  void
  JointProblem::save_checkpoint(const unsigned int increment, const double t)
  {
    ghosted = solution;
    parallel::distributed::SolutionTransfer<dim, PETScWrappers::MPI::Vector> transfer(
      dof_handler);
    PETScWrappers::MPI::Vector ghosted_previous(owned_dofs, relevant_dofs, comm);
    ghosted_previous = previous;
    transfer.prepare_for_serialization(
      std::vector<const PETScWrappers::MPI::Vector *>{&ghosted, &ghosted_previous});
    const unsigned int nq = quadrature.size();
    triangulation.register_data_attach(
      [this, nq](const typename Triangulation<dim>::cell_iterator &cell,
                 const typename Triangulation<dim>::CellStatus) {
        std::vector<char> bytes;
        if (!in_layer(cell))
          return bytes;
        bytes.resize(nq * state_size * sizeof(double));
        char *b = bytes.data();
        for (const auto &p : storage.get_data(cell))
          {
            std::memcpy(b, p->committed.data(), state_size * sizeof(double));
            b += state_size * sizeof(double);
          }
        return bytes;
      },
      true);
    triangulation.save(settings.output_dir + "/checkpoint");
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream f(settings.output_dir + "/checkpoint.txt");
        f << increment << ' ' << std::setprecision(17) << t << ' ' << dt_previous << '\n';
        for (const auto &r : curve_rows)
          f << r << '\n';
        if (!f)
          throw std::runtime_error("cannot write " + settings.output_dir + "/checkpoint.txt");
      }
  }

  unsigned int
  JointProblem::load_checkpoint(double &t)
  {
    std::ifstream f(settings.output_dir + "/checkpoint.txt");
    unsigned int  increment = 0;
    if (!(f >> increment >> t >> dt_previous))
      throw std::runtime_error("no checkpoint in " + settings.output_dir);
    std::string line;
    std::getline(f, line);
    while (std::getline(f, line))
      if (!line.empty())
        curve_rows.push_back(line);

    triangulation.load(settings.output_dir + "/checkpoint");
    setup_system();
    parallel::distributed::SolutionTransfer<dim, PETScWrappers::MPI::Vector> transfer(
      dof_handler);
    std::vector<PETScWrappers::MPI::Vector *> vectors{&solution, &previous};
    transfer.deserialize(vectors);
    initialise_state();
    const unsigned int nq     = quadrature.size();
    const unsigned int handle = triangulation.register_data_attach(
      [](const typename Triangulation<dim>::cell_iterator &,
         const typename Triangulation<dim>::CellStatus) { return std::vector<char>(); },
      true);
    triangulation.notify_ready_to_unpack(
      handle,
      [this, nq](const typename Triangulation<dim>::cell_iterator &cell,
                 const typename Triangulation<dim>::CellStatus,
                 const boost::iterator_range<std::vector<char>::const_iterator> &range) {
        if (!in_layer(cell))
          return;
        if (static_cast<size_t>(range.size()) != nq * state_size * sizeof(double))
          throw std::runtime_error("a checkpoint's cell holds " +
                                   std::to_string(range.size()) + " bytes, not " +
                                   std::to_string(nq * state_size * sizeof(double)));
        const char *b = &*range.begin();
        for (auto &p : storage.get_data(cell))
          {
            std::memcpy(p->committed.data(), b, state_size * sizeof(double));
            b += state_size * sizeof(double);
          }
      });
    return increment;
  }

  void
  JointProblem::run()
  {
    make_grid();
    unsigned int done = 0;
    double       t    = 0;
    if (settings.restart)
      done = load_checkpoint(t);
    else
      {
        triangulation.refine_global(settings.refine);
        setup_system();
        initialise_state();
      }
    force_scale = std::abs(settings.normal) * settings.length * settings.length;
    if (!(force_scale > 0))
      force_scale = settings.e_block * settings.length * settings.length * 1e-6;

    size_t n_points = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_layer(cell))
        n_points += quadrature.size();
    n_points = Utilities::MPI::sum(n_points, comm);
    pcout << "interlock_dealii: scene " << settings.scene << ", "
          << Utilities::MPI::n_mpi_processes(comm) << " processes, "
          << triangulation.n_global_active_cells() << " cells, " << dof_handler.n_dofs()
          << " dofs, " << n_points << " interface points, interlock " << interlock_version()
          << (settings.restart ? ", restarted after increment " + std::to_string(done) : "")
          << std::endl;

    Cost                       cost;
    const auto                 t_start = Clock::now();
    const double               dt_min  = 1e-6;
    const unsigned int         n_total = 1 + settings.n_slip;
    PETScWrappers::MPI::Vector last(owned_dofs, comm);
    for (unsigned int increment = done + 1; increment <= n_total; ++increment)
      {
        const double t_end      = increment;
        double       dt         = t_end - t;
        unsigned int substeps   = 0, iterations = 0;
        while (t < t_end)
          {
            dt                    = std::min(dt, t_end - t);
            const double t_new    = (t_end - t - dt <= 1e-12) ? t_end : t + dt;
            last                  = solution;
            // In the slip phase the last substep's rate carries on: the layer's points start
            // Newton off the state they converged to (where a point that slid sits on its
            // friction cone to round-off, and its tangent would depend on the partition).
            if (dt_previous > 0 && t - dt_previous >= 1.0 - 1e-12)
              {
                PETScWrappers::MPI::Vector rate = last;
                rate -= previous;
                solution.add((t_new - t) / dt_previous, rate);
              }
            current_normal        = settings.normal * normal_factor(t_new);
            set_platen(t_new);
            double     fraction   = 1;
            const bool converged  = newton(cost, iterations, fraction);
            // A converged iterate whose points ask for a cut is accepted all the same once the
            // step cannot be cut further (the request is about accuracy, not failure).
            const double cut = converged ? std::max(fraction, 0.01) : std::min(fraction, 0.5);
            if (!converged || (fraction < 1 && dt * cut >= dt_min))
              {
                if (!(fraction > 0))
                  throw std::runtime_error("a layer point refuses its input");
                if (settings.verbose > 0)
                  pcout << "    cut back by " << cut << " at t = " << t_new
                        << (converged ? " (a point asks for it)" : " (no convergence)")
                        << std::endl;
                solution = last;
                if (dt * cut < dt_min)
                  throw std::runtime_error("increment " + std::to_string(increment) +
                                           ": the step would fall below " +
                                           std::to_string(dt_min));
                dt *= cut;
                continue;
              }
            commit_state();
            previous    = last;
            dt_previous = t_new - t;
            t           = t_new;
            ++substeps;
            dt *= 2;
          }
        curve_rows.push_back(curve_row(increment, t, substeps, iterations));
        pcout << "  increment " << std::setw(3) << increment << ": " << substeps
              << " substeps, " << iterations << " Newton iterations" << std::endl;
        if (settings.vtu_every > 0 && increment % settings.vtu_every == 0)
          write_vtu(increment);
        if (settings.checkpoint_after == static_cast<int>(increment))
          {
            save_checkpoint(increment, t);
            pcout << "  checkpoint after increment " << increment << " in "
                  << settings.output_dir << std::endl;
            break;
          }
      }
    const double wall = std::chrono::duration<double>(Clock::now() - t_start).count();

    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream f(settings.output_dir + "/" + settings.curve);
        f << curve_header << '\n';
        for (const auto &r : curve_rows)
          f << r << '\n';
        if (!f)
          throw std::runtime_error("cannot write the curve");
      }
    // The cost split per Newton iteration, the slowest process's; the memory per interface
    // point: its state in the cell storage (with the storage's pointer, its control block and
    // the vector's header) and its share of the batch (old and new state, separation,
    // traction, tangent, step fraction, status).
    const unsigned int its = std::max(1u, cost.iterations);
    const double       bytes =
      sizeof(double) * (3.0 * state_size + 3 + 3 + 9 + 1) + sizeof(int) + sizeof(PointState) +
      sizeof(std::shared_ptr<PointState>) + 2 * sizeof(void *);
    pcout << std::setprecision(4) << "cost: processes " << Utilities::MPI::n_mpi_processes(comm)
          << " points " << n_points << " dofs " << dof_handler.n_dofs() << " iterations "
          << cost.iterations << " law_s "
          << Utilities::MPI::max(cost.law, comm) / its << " assembly_s "
          << Utilities::MPI::max(cost.assembly, comm) / its << " solve_s "
          << Utilities::MPI::max(cost.solve, comm) / its << " law_cpu_s "
          << Utilities::MPI::max(cost.law_cpu, comm) / its << " assembly_cpu_s "
          << Utilities::MPI::max(cost.assembly_cpu, comm) / its << " solve_cpu_s "
          << Utilities::MPI::max(cost.solve_cpu, comm) / its << " wall_s " << wall
          << " bytes_per_point " << bytes << std::endl;
  }
} // namespace interlock_dealii

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      interlock_dealii::Settings settings;
      settings.parse(argc, argv);
      interlock_dealii::JointProblem problem(settings);
      problem.run();
    }
  catch (const std::exception &e)
    {
      std::cerr << "interlock_dealii: " << e.what() << std::endl;
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
  return 0;
}
