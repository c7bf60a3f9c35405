/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for metric_forms() of
 * generated/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 1ffd02983b32fea1953b31d6b4da6e985de5a598f8e69763f0a5d6374958d5e8
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na2_metric_forms_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_fmin CASADI_PREFIX(fmin)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_s6 CASADI_PREFIX(s6)
#define casadi_s7 CASADI_PREFIX(s7)
#define casadi_sq CASADI_PREFIX(sq)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

casadi_real casadi_fmin(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x<y ? x : y;
#else
  return fmin(x, y);
#endif
}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na2_metric_forms_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {5, 1, 1};
static const casadi_int casadi_s1[3] = {25, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {2, 1, 1};
static const casadi_int casadi_s5[3] = {4, 1, 1};
static const casadi_int casadi_s6[3] = {2, 2, 1};
static const casadi_int casadi_s7[3] = {1, 2, 1};

/* snakecg_na2_metric_forms:(q[5],K[25],contact_link[3],side,object_mass,object_inertia,q_obj[3],rho[2],wheel_offset[3],free[4],regularization)->(omega_tau[2x2],xi_tau[2x2],lambda_form_tau[2x2],input_metric[2x2],contact_from_tau[1x2],pivot_ratio) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106, a107;
  casadi_real a108;
  a000=arg[2]? arg[2][0] : 0;
  a001=arg[0]? arg[0][2] : 0;
  a002=sin(a001);
  a003=(a000*a002);
  a004=arg[2]? arg[2][1] : 0;
  a005=arg[0]? arg[0][3] : 0;
  a006=cos(a005);
  a007=(a002*a006);
  a001=cos(a001);
  a005=sin(a005);
  a008=(a001*a005);
  a007=(a007+a008);
  a009=(a004*a007);
  a003=(a003+a009);
  a009=arg[2]? arg[2][2] : 0;
  a010=arg[0]? arg[0][4] : 0;
  a011=cos(a010);
  a012=(a007*a011);
  a013=(a001*a006);
  a005=(a002*a005);
  a013=(a013-a005);
  a010=sin(a010);
  a005=(a013*a010);
  a012=(a012+a005);
  a014=(a009*a012);
  a003=(a003+a014);
  a014=arg[3]? arg[3][0] : 0;
  a015=(a003*a014);
  a016=arg[4]? arg[4][0] : 0;
  a017=(a015/a016);
  a018=arg[9]? arg[9][0] : 0;
  a019=(a000+a004);
  a019=(a019+a009);
  a020=(a015*a019);
  a021=arg[1]? arg[1][15] : 0;
  a006=(a006*a002);
  a008=(a008+a006);
  a006=(a011*a008);
  a005=(a005+a006);
  a006=(a021*a005);
  a022=arg[1]? arg[1][14] : 0;
  a023=(a022*a008);
  a023=(a006+a023);
  a024=arg[1]? arg[1][13] : 0;
  a025=(a024*a002);
  a025=(a023+a025);
  a026=arg[1]? arg[1][12] : 0;
  a027=(a025/a026);
  a011=(a013*a011);
  a028=(a008*a010);
  a028=(a011-a028);
  a021=(a021*a028);
  a029=arg[1]? arg[1][4] : 0;
  a030=(a013*a029);
  a030=(a021*a030);
  a031=(a008*a029);
  a031=(a006*a031);
  a030=(a030+a031);
  a031=arg[1]? arg[1][24] : 0;
  a032=(a030+a031);
  a033=arg[1]? arg[1][3] : 0;
  a034=arg[1]? arg[1][9] : 0;
  a033=(a033-a034);
  a035=(a001*a033);
  a036=(a021*a035);
  a033=(a033*a002);
  a037=(a006*a033);
  a036=(a036+a037);
  a036=(a032+a036);
  a037=(a006/a026);
  a038=(a037*a027);
  a038=(a038*a026);
  a038=(a036-a038);
  a039=(a021/a026);
  a022=(a022*a013);
  a022=(a021+a022);
  a024=(a024*a001);
  a024=(a022+a024);
  a040=(a024/a026);
  a041=(a039*a040);
  a041=(a041*a026);
  a038=(a038-a041);
  a030=(a032+a030);
  a041=arg[1]? arg[1][23] : 0;
  a030=(a030+a041);
  a041=(a022*a035);
  a042=(a023*a033);
  a041=(a041+a042);
  a042=(a030+a041);
  a041=(a042+a041);
  a043=arg[1]? arg[1][22] : 0;
  a041=(a041+a043);
  a043=casadi_sq(a027);
  a043=(a043*a026);
  a043=(a041-a043);
  a044=casadi_sq(a040);
  a044=(a044*a026);
  a043=(a043-a044);
  a038=(a038/a043);
  a044=(a023/a026);
  a045=(a037*a044);
  a045=(a045*a026);
  a045=(a032-a045);
  a046=(a022/a026);
  a047=(a039*a046);
  a047=(a047*a026);
  a045=(a045-a047);
  a047=(a044*a027);
  a047=(a047*a026);
  a047=(a042-a047);
  a048=(a046*a040);
  a048=(a048*a026);
  a047=(a047-a048);
  a047=(a047/a043);
  a048=(a038*a047);
  a048=(a048*a043);
  a045=(a045-a048);
  a048=casadi_sq(a044);
  a048=(a048*a026);
  a048=(a030-a048);
  a049=casadi_sq(a046);
  a049=(a049*a026);
  a048=(a048-a049);
  a049=casadi_sq(a047);
  a049=(a049*a043);
  a048=(a048-a049);
  a045=(a045/a048);
  a049=casadi_sq(a037);
  a049=(a049*a026);
  a049=(a031-a049);
  a050=casadi_sq(a039);
  a050=(a050*a026);
  a049=(a049-a050);
  a050=casadi_sq(a038);
  a050=(a050*a043);
  a049=(a049-a050);
  a050=casadi_sq(a045);
  a050=(a050*a048);
  a049=(a049-a050);
  a050=(a045/a049);
  a051=(a038*a050);
  a052=(1./a048);
  a053=(a045*a050);
  a052=(a052+a053);
  a053=(a047*a052);
  a051=(a051-a053);
  a053=(a027*a051);
  a054=(a044*a052);
  a053=(a053+a054);
  a054=(a037*a050);
  a053=(a053-a054);
  a054=(a020*a053);
  a055=(a000*a001);
  a056=(a004*a013);
  a055=(a055+a056);
  a010=(a007*a010);
  a011=(a011-a010);
  a010=(a009*a011);
  a055=(a055+a010);
  a010=(a055*a014);
  a056=(a010*a019);
  a057=(a039*a050);
  a058=(a040*a051);
  a059=(a046*a052);
  a058=(a058+a059);
  a057=(a057-a058);
  a058=(a056*a057);
  a054=(a054-a058);
  a058=arg[0]? arg[0][1] : 0;
  a033=(a058+a033);
  a059=arg[1]? arg[1][10] : 0;
  a060=(a008*a059);
  a061=(a033+a060);
  a062=(a058-a061);
  a063=(a004*a062);
  a029=(a029-a059);
  a008=(a029*a008);
  a008=(a061+a008);
  a064=arg[1]? arg[1][11] : 0;
  a005=(a005*a064);
  a008=(a008+a005);
  a065=(a058-a008);
  a066=(a009*a065);
  a063=(a063+a066);
  a063=(a015*a063);
  a066=arg[0]? arg[0][0] : 0;
  a035=(a066+a035);
  a067=(a013*a059);
  a068=(a035+a067);
  a069=(a068-a066);
  a070=(a004*a069);
  a029=(a013*a029);
  a029=(a068+a029);
  a028=(a028*a064);
  a029=(a029+a028);
  a071=(a029-a066);
  a072=(a009*a071);
  a070=(a070+a072);
  a070=(a010*a070);
  a063=(a063-a070);
  a034=(a034*a000);
  a059=(a059*a004);
  a034=(a034+a059);
  a064=(a064*a009);
  a034=(a034+a064);
  a064=(a014*a034);
  a059=casadi_sq(a003);
  a059=(a064*a059);
  a070=casadi_sq(a055);
  a064=(a064*a070);
  a059=(a059+a064);
  a064=arg[6]? arg[6][2] : 0;
  a070=cos(a064);
  a072=arg[7]? arg[7][1] : 0;
  a073=(a070*a072);
  a064=sin(a064);
  a074=arg[7]? arg[7][0] : 0;
  a075=(a064*a074);
  a073=(a073+a075);
  a075=arg[6]? arg[6][1] : 0;
  a075=(a073+a075);
  a003=(a003*a034);
  a075=(a075+a003);
  a058=(a058*a000);
  a061=(a061*a004);
  a058=(a058+a061);
  a061=(a008*a009);
  a058=(a058+a061);
  a075=(a075-a058);
  a075=(a015*a075);
  a059=(a059-a075);
  a070=(a070*a074);
  a064=(a064*a072);
  a070=(a070-a064);
  a064=arg[6]? arg[6][0] : 0;
  a064=(a070+a064);
  a034=(a055*a034);
  a064=(a064+a034);
  a066=(a066*a000);
  a068=(a068*a004);
  a066=(a066+a068);
  a068=(a029*a009);
  a066=(a066+a068);
  a064=(a064-a066);
  a064=(a010*a064);
  a059=(a059-a064);
  a019=(a059*a019);
  a063=(a063+a019);
  a019=(a063*a051);
  a054=(a054+a019);
  a033=(a033-a008);
  a008=(a009*a033);
  a019=(a004*a060);
  a008=(a008-a019);
  a008=(a015*a008);
  a019=(a004*a067);
  a029=(a029-a035);
  a035=(a009*a029);
  a019=(a019+a035);
  a019=(a010*a019);
  a008=(a008-a019);
  a004=(a004+a009);
  a004=(a059*a004);
  a008=(a008+a004);
  a004=(a008*a052);
  a054=(a054+a004);
  a059=(a059*a009);
  a004=(a009*a005);
  a004=(a015*a004);
  a009=(a009*a028);
  a009=(a010*a009);
  a004=(a004+a009);
  a059=(a059-a004);
  a004=(a059*a050);
  a054=(a054-a004);
  a054=(a018*a054);
  a004=(a020/a026);
  a009=(a027*a020);
  a009=(a063+a009);
  a019=(a040*a056);
  a009=(a009+a019);
  a019=(a009/a043);
  a035=(a044*a020);
  a035=(a008+a035);
  a064=(a046*a056);
  a035=(a035+a064);
  a064=(a047*a009);
  a035=(a035-a064);
  a064=(a035/a048);
  a066=(a037*a020);
  a066=(a059+a066);
  a068=(a039*a056);
  a066=(a066+a068);
  a009=(a038*a009);
  a066=(a066-a009);
  a035=(a045*a035);
  a066=(a066-a035);
  a066=(a066/a049);
  a035=(a045*a066);
  a064=(a064-a035);
  a035=(a047*a064);
  a019=(a019-a035);
  a035=(a038*a066);
  a019=(a019-a035);
  a035=(a027*a019);
  a004=(a004+a035);
  a035=(a044*a064);
  a004=(a004+a035);
  a035=(a037*a066);
  a004=(a004+a035);
  a035=(a020*a004);
  a009=(a056/a026);
  a068=(a040*a019);
  a009=(a009+a068);
  a068=(a046*a064);
  a009=(a009+a068);
  a068=(a039*a066);
  a009=(a009+a068);
  a068=(a056*a009);
  a035=(a035+a068);
  a068=(a063*a019);
  a035=(a035+a068);
  a068=(a008*a064);
  a035=(a035+a068);
  a068=(a059*a066);
  a035=(a035+a068);
  a068=(a015*a017);
  a000=(a010/a016);
  a010=(a010*a000);
  a068=(a068+a010);
  a055=(a055*a070);
  a055=(a055*a014);
  a015=(a015*a073);
  a055=(a055+a015);
  a015=arg[5]? arg[5][0] : 0;
  a073=(a055/a015);
  a055=(a055*a073);
  a068=(a068+a055);
  a035=(a035+a068);
  a068=(a018*a035);
  a068=(a068*a018);
  a055=1.;
  a014=(a055-a018);
  a068=(a068+a014);
  a014=arg[10]? arg[10][0] : 0;
  a070=(a014*a018);
  a068=(a068+a070);
  a070=(a054/a068);
  a010=arg[9]? arg[9][1] : 0;
  a034=arg[8]? arg[8][0] : 0;
  a072=(a034*a019);
  a074=(a002*a004);
  a075=(a001*a009);
  a074=(a074+a075);
  a072=(a072-a074);
  a074=(a010*a072);
  a074=(a074*a018);
  a074=(a074/a068);
  a075=(a001*a057);
  a058=(a002*a053);
  a075=(a075-a058);
  a058=(a034*a051);
  a075=(a075+a058);
  a075=(a010*a075);
  a058=(a074*a054);
  a075=(a075-a058);
  a058=(a001/a026);
  a061=(a027*a002);
  a061=(a034-a061);
  a003=(a040*a001);
  a061=(a061-a003);
  a003=(a061/a043);
  a076=(a044*a002);
  a077=(a046*a001);
  a076=(a076+a077);
  a077=(a047*a061);
  a076=(a076+a077);
  a077=(a076/a048);
  a076=(a045*a076);
  a078=(a037*a002);
  a079=(a039*a001);
  a078=(a078+a079);
  a061=(a038*a061);
  a078=(a078+a061);
  a076=(a076-a078);
  a076=(a076/a049);
  a078=(a045*a076);
  a077=(a077+a078);
  a078=(a047*a077);
  a003=(a003+a078);
  a078=(a038*a076);
  a003=(a003-a078);
  a078=(a040*a003);
  a058=(a058-a078);
  a078=(a046*a077);
  a058=(a058+a078);
  a078=(a039*a076);
  a058=(a058-a078);
  a078=(a001*a058);
  a061=(a027*a003);
  a079=(a002/a026);
  a061=(a061-a079);
  a079=(a044*a077);
  a061=(a061-a079);
  a079=(a037*a076);
  a061=(a061+a079);
  a079=(a002*a061);
  a078=(a078-a079);
  a079=(a034*a003);
  a078=(a078+a079);
  a079=(a010*a078);
  a079=(a079*a010);
  a080=(a055-a010);
  a079=(a079+a080);
  a080=(a014*a010);
  a079=(a079+a080);
  a080=casadi_sq(a074);
  a080=(a080*a068);
  a080=(a079-a080);
  a081=(a075/a080);
  a082=arg[9]? arg[9][2] : 0;
  a083=(a013*a058);
  a084=(a007*a061);
  a083=(a083-a084);
  a069=(a013*a069);
  a062=(a007*a062);
  a069=(a069-a062);
  a062=arg[8]? arg[8][1] : 0;
  a069=(a069+a062);
  a084=(a069*a003);
  a083=(a083+a084);
  a060=(a007*a060);
  a067=(a013*a067);
  a060=(a060+a067);
  a060=(a060+a062);
  a062=(a060*a077);
  a083=(a083-a062);
  a062=(a082*a083);
  a062=(a062*a010);
  a067=(a069*a019);
  a084=(a007*a004);
  a085=(a013*a009);
  a084=(a084+a085);
  a067=(a067-a084);
  a084=(a060*a064);
  a067=(a067+a084);
  a084=(a082*a067);
  a084=(a084*a018);
  a084=(a084/a068);
  a085=(a084*a074);
  a085=(a085*a068);
  a062=(a062-a085);
  a062=(a062/a080);
  a085=(a013*a057);
  a086=(a007*a053);
  a085=(a085-a086);
  a086=(a069*a051);
  a085=(a085+a086);
  a086=(a060*a052);
  a085=(a085+a086);
  a085=(a082*a085);
  a086=(a084*a054);
  a085=(a085-a086);
  a086=(a062*a075);
  a085=(a085-a086);
  a086=(a013/a026);
  a087=(a027*a007);
  a087=(a069-a087);
  a088=(a040*a013);
  a087=(a087-a088);
  a088=(a087/a043);
  a089=(a044*a007);
  a089=(a060-a089);
  a090=(a046*a013);
  a089=(a089-a090);
  a090=(a047*a087);
  a089=(a089-a090);
  a090=(a089/a048);
  a091=(a037*a007);
  a092=(a039*a013);
  a091=(a091+a092);
  a087=(a038*a087);
  a091=(a091+a087);
  a089=(a045*a089);
  a091=(a091+a089);
  a091=(a091/a049);
  a089=(a045*a091);
  a090=(a090+a089);
  a089=(a047*a090);
  a088=(a088-a089);
  a089=(a038*a091);
  a088=(a088+a089);
  a089=(a040*a088);
  a086=(a086-a089);
  a089=(a046*a090);
  a086=(a086-a089);
  a089=(a039*a091);
  a086=(a086+a089);
  a089=(a013*a086);
  a087=(a027*a088);
  a092=(a007/a026);
  a087=(a087-a092);
  a092=(a044*a090);
  a087=(a087+a092);
  a092=(a037*a091);
  a087=(a087-a092);
  a092=(a007*a087);
  a089=(a089-a092);
  a092=(a069*a088);
  a089=(a089+a092);
  a092=(a060*a090);
  a089=(a089+a092);
  a092=(a082*a089);
  a092=(a092*a082);
  a093=(a055-a082);
  a092=(a092+a093);
  a093=(a014*a082);
  a092=(a092+a093);
  a093=casadi_sq(a084);
  a093=(a093*a068);
  a093=(a092-a093);
  a094=casadi_sq(a062);
  a094=(a094*a080);
  a093=(a093-a094);
  a094=(a085/a093);
  a095=arg[9]? arg[9][3] : 0;
  a096=(a011*a086);
  a097=(a012*a087);
  a096=(a096-a097);
  a071=(a011*a071);
  a065=(a012*a065);
  a071=(a071-a065);
  a065=arg[8]? arg[8][2] : 0;
  a071=(a071+a065);
  a097=(a071*a088);
  a096=(a096+a097);
  a029=(a011*a029);
  a033=(a012*a033);
  a029=(a029-a033);
  a029=(a029+a065);
  a033=(a029*a090);
  a096=(a096+a033);
  a005=(a012*a005);
  a028=(a011*a028);
  a005=(a005+a028);
  a005=(a005+a065);
  a065=(a005*a091);
  a096=(a096-a065);
  a065=(a095*a096);
  a065=(a065*a082);
  a028=(a071*a019);
  a033=(a012*a004);
  a097=(a011*a009);
  a033=(a033+a097);
  a028=(a028-a033);
  a033=(a029*a064);
  a028=(a028+a033);
  a033=(a005*a066);
  a028=(a028+a033);
  a033=(a095*a028);
  a033=(a033*a018);
  a033=(a033/a068);
  a097=(a033*a084);
  a097=(a097*a068);
  a065=(a065-a097);
  a097=(a011*a058);
  a098=(a012*a061);
  a097=(a097-a098);
  a098=(a071*a003);
  a097=(a097+a098);
  a098=(a029*a077);
  a097=(a097-a098);
  a098=(a005*a076);
  a097=(a097+a098);
  a098=(a095*a097);
  a098=(a098*a010);
  a099=(a033*a074);
  a099=(a099*a068);
  a098=(a098-a099);
  a098=(a098/a080);
  a099=(a098*a062);
  a099=(a099*a080);
  a065=(a065-a099);
  a065=(a065/a093);
  a099=(a011*a057);
  a100=(a012*a053);
  a099=(a099-a100);
  a100=(a071*a051);
  a099=(a099+a100);
  a100=(a029*a052);
  a099=(a099+a100);
  a100=(a005*a050);
  a099=(a099-a100);
  a099=(a095*a099);
  a054=(a033*a054);
  a099=(a099-a054);
  a075=(a098*a075);
  a099=(a099-a075);
  a085=(a065*a085);
  a099=(a099-a085);
  a085=(a011/a026);
  a075=(a027*a012);
  a075=(a071-a075);
  a054=(a040*a011);
  a075=(a075-a054);
  a043=(a075/a043);
  a054=(a044*a012);
  a054=(a029-a054);
  a100=(a046*a011);
  a054=(a054-a100);
  a100=(a047*a075);
  a054=(a054-a100);
  a048=(a054/a048);
  a100=(a037*a012);
  a100=(a005-a100);
  a101=(a039*a011);
  a100=(a100-a101);
  a075=(a038*a075);
  a100=(a100-a075);
  a054=(a045*a054);
  a100=(a100-a054);
  a100=(a100/a049);
  a045=(a045*a100);
  a048=(a048-a045);
  a045=(a047*a048);
  a043=(a043-a045);
  a045=(a038*a100);
  a043=(a043-a045);
  a045=(a040*a043);
  a085=(a085-a045);
  a045=(a046*a048);
  a085=(a085-a045);
  a045=(a039*a100);
  a085=(a085-a045);
  a045=(a011*a085);
  a054=(a027*a043);
  a075=(a012/a026);
  a054=(a054-a075);
  a075=(a044*a048);
  a054=(a054+a075);
  a075=(a037*a100);
  a054=(a054+a075);
  a075=(a012*a054);
  a045=(a045-a075);
  a075=(a071*a043);
  a045=(a045+a075);
  a075=(a029*a048);
  a045=(a045+a075);
  a075=(a005*a100);
  a045=(a045+a075);
  a075=(a095*a045);
  a075=(a075*a095);
  a101=(a055-a095);
  a075=(a075+a101);
  a014=(a014*a095);
  a075=(a075+a014);
  a014=casadi_sq(a033);
  a014=(a014*a068);
  a014=(a075-a014);
  a101=casadi_sq(a098);
  a101=(a101*a080);
  a014=(a014-a101);
  a101=casadi_sq(a065);
  a101=(a101*a093);
  a014=(a014-a101);
  a099=(a099/a014);
  a101=(a065*a099);
  a094=(a094-a101);
  a101=(a062*a094);
  a081=(a081-a101);
  a101=(a098*a099);
  a081=(a081-a101);
  a101=(a074*a081);
  a070=(a070-a101);
  a101=(a084*a094);
  a070=(a070-a101);
  a101=(a033*a099);
  a070=(a070-a101);
  a101=(a017*a070);
  a102=(a101*a016);
  a103=(a102*a101);
  a104=(a000*a070);
  a105=(a104*a016);
  a106=(a105*a104);
  a103=(a103+a106);
  a106=(a073*a070);
  a107=(a106*a015);
  a108=(a107*a106);
  a103=(a103+a108);
  if (res[0]!=0) res[0][0]=a103;
  a047=(a047*a050);
  a038=(a038/a049);
  a047=(a047-a038);
  a027=(a027*a047);
  a044=(a044*a050);
  a027=(a027-a044);
  a037=(a037/a049);
  a027=(a027+a037);
  a037=(a020*a027);
  a046=(a046*a050);
  a040=(a040*a047);
  a046=(a046-a040);
  a039=(a039/a049);
  a046=(a046-a039);
  a039=(a056*a046);
  a037=(a037-a039);
  a039=(a063*a047);
  a037=(a037+a039);
  a039=(a008*a050);
  a037=(a037-a039);
  a039=(a059/a049);
  a037=(a037+a039);
  a018=(a018*a037);
  a068=(a018/a068);
  a037=(a001*a046);
  a039=(a002*a027);
  a037=(a037-a039);
  a039=(a034*a047);
  a037=(a037+a039);
  a010=(a010*a037);
  a037=(a074*a018);
  a010=(a010-a037);
  a037=(a010/a080);
  a039=(a013*a046);
  a040=(a007*a027);
  a039=(a039-a040);
  a040=(a069*a047);
  a039=(a039+a040);
  a040=(a060*a050);
  a039=(a039-a040);
  a082=(a082*a039);
  a039=(a084*a018);
  a082=(a082-a039);
  a039=(a062*a010);
  a082=(a082-a039);
  a039=(a082/a093);
  a011=(a011*a046);
  a012=(a012*a027);
  a011=(a011-a012);
  a071=(a071*a047);
  a011=(a011+a071);
  a029=(a029*a050);
  a011=(a011-a029);
  a005=(a005/a049);
  a011=(a011+a005);
  a095=(a095*a011);
  a018=(a033*a018);
  a095=(a095-a018);
  a010=(a098*a010);
  a095=(a095-a010);
  a082=(a065*a082);
  a095=(a095-a082);
  a095=(a095/a014);
  a065=(a065*a095);
  a039=(a039-a065);
  a062=(a062*a039);
  a037=(a037-a062);
  a098=(a098*a095);
  a037=(a037-a098);
  a074=(a074*a037);
  a068=(a068-a074);
  a084=(a084*a039);
  a068=(a068-a084);
  a033=(a033*a095);
  a068=(a068-a033);
  a017=(a017*a068);
  a033=(a017*a016);
  a101=(a033*a101);
  a000=(a000*a068);
  a016=(a000*a016);
  a104=(a016*a104);
  a101=(a101+a104);
  a073=(a073*a068);
  a015=(a073*a015);
  a106=(a015*a106);
  a101=(a101+a106);
  if (res[0]!=0) res[0][1]=a101;
  a102=(a102*a017);
  a105=(a105*a000);
  a102=(a102+a105);
  a107=(a107*a073);
  a102=(a102+a107);
  if (res[0]!=0) res[0][2]=a102;
  a033=(a033*a017);
  a016=(a016*a000);
  a033=(a033+a016);
  a015=(a015*a073);
  a033=(a033+a015);
  if (res[0]!=0) res[0][3]=a033;
  a033=(a004*a070);
  a015=(a061*a081);
  a033=(a033+a015);
  a015=(a087*a094);
  a033=(a033+a015);
  a015=(a054*a099);
  a033=(a033+a015);
  a053=(a053-a033);
  a033=(a053*a026);
  a015=(a019*a070);
  a073=(a003*a081);
  a015=(a015+a073);
  a073=(a088*a094);
  a015=(a015+a073);
  a073=(a043*a099);
  a015=(a015+a073);
  a051=(a051-a015);
  a015=(a051*a025);
  a033=(a033-a015);
  a015=(a077*a081);
  a073=(a064*a070);
  a015=(a015-a073);
  a073=(a090*a094);
  a015=(a015-a073);
  a073=(a048*a099);
  a015=(a015-a073);
  a015=(a052+a015);
  a073=(a015*a023);
  a033=(a033-a073);
  a073=(a091*a094);
  a016=(a066*a070);
  a000=(a076*a081);
  a016=(a016+a000);
  a073=(a073-a016);
  a016=(a100*a099);
  a073=(a073-a016);
  a073=(a073-a050);
  a016=(a073*a006);
  a033=(a033-a016);
  a016=(a033*a053);
  a000=(a009*a070);
  a017=(a058*a081);
  a000=(a000-a017);
  a017=(a086*a094);
  a000=(a000-a017);
  a017=(a085*a099);
  a000=(a000-a017);
  a057=(a057+a000);
  a000=(a057*a026);
  a017=(a051*a024);
  a000=(a000+a017);
  a017=(a015*a022);
  a000=(a000+a017);
  a017=(a073*a021);
  a000=(a000+a017);
  a017=(a000*a057);
  a016=(a016+a017);
  a017=(a057*a024);
  a102=(a053*a025);
  a017=(a017-a102);
  a102=(a051*a041);
  a017=(a017+a102);
  a102=(a015*a042);
  a017=(a017+a102);
  a102=(a073*a036);
  a017=(a017+a102);
  a102=(a017*a051);
  a016=(a016+a102);
  a102=(a057*a022);
  a107=(a053*a023);
  a102=(a102-a107);
  a107=(a051*a042);
  a102=(a102+a107);
  a107=(a015*a030);
  a102=(a102+a107);
  a107=(a073*a032);
  a102=(a102+a107);
  a107=(a102*a015);
  a016=(a016+a107);
  a107=(a057*a021);
  a105=(a053*a006);
  a107=(a107-a105);
  a105=(a051*a036);
  a107=(a107+a105);
  a105=(a015*a032);
  a107=(a107+a105);
  a105=(a073*a031);
  a107=(a107+a105);
  a105=(a107*a073);
  a016=(a016+a105);
  if (res[1]!=0) res[1][0]=a016;
  a004=(a004*a068);
  a016=(a061*a037);
  a004=(a004+a016);
  a016=(a087*a039);
  a004=(a004+a016);
  a016=(a054*a095);
  a004=(a004+a016);
  a027=(a027-a004);
  a004=(a027*a026);
  a019=(a019*a068);
  a016=(a003*a037);
  a019=(a019+a016);
  a016=(a088*a039);
  a019=(a019+a016);
  a016=(a043*a095);
  a019=(a019+a016);
  a047=(a047-a019);
  a019=(a047*a025);
  a004=(a004-a019);
  a019=(a077*a037);
  a064=(a064*a068);
  a019=(a019-a064);
  a064=(a090*a039);
  a019=(a019-a064);
  a064=(a048*a095);
  a019=(a019-a064);
  a019=(a019-a050);
  a064=(a019*a023);
  a004=(a004-a064);
  a049=(1./a049);
  a064=(a091*a039);
  a066=(a066*a068);
  a016=(a076*a037);
  a066=(a066+a016);
  a064=(a064-a066);
  a066=(a100*a095);
  a064=(a064-a066);
  a064=(a049+a064);
  a066=(a064*a006);
  a004=(a004-a066);
  a053=(a004*a053);
  a009=(a009*a068);
  a066=(a058*a037);
  a009=(a009-a066);
  a066=(a086*a039);
  a009=(a009-a066);
  a066=(a085*a095);
  a009=(a009-a066);
  a046=(a046+a009);
  a026=(a046*a026);
  a009=(a047*a024);
  a026=(a026+a009);
  a009=(a019*a022);
  a026=(a026+a009);
  a009=(a064*a021);
  a026=(a026+a009);
  a057=(a026*a057);
  a053=(a053+a057);
  a024=(a046*a024);
  a025=(a027*a025);
  a024=(a024-a025);
  a041=(a047*a041);
  a024=(a024+a041);
  a041=(a019*a042);
  a024=(a024+a041);
  a041=(a064*a036);
  a024=(a024+a041);
  a051=(a024*a051);
  a053=(a053+a051);
  a022=(a046*a022);
  a023=(a027*a023);
  a022=(a022-a023);
  a042=(a047*a042);
  a022=(a022+a042);
  a030=(a019*a030);
  a022=(a022+a030);
  a030=(a064*a032);
  a022=(a022+a030);
  a015=(a022*a015);
  a053=(a053+a015);
  a021=(a046*a021);
  a006=(a027*a006);
  a021=(a021-a006);
  a036=(a047*a036);
  a021=(a021+a036);
  a032=(a019*a032);
  a021=(a021+a032);
  a031=(a064*a031);
  a021=(a021+a031);
  a073=(a021*a073);
  a053=(a053+a073);
  if (res[1]!=0) res[1][1]=a053;
  a033=(a033*a027);
  a000=(a000*a046);
  a033=(a033+a000);
  a017=(a017*a047);
  a033=(a033+a017);
  a102=(a102*a019);
  a033=(a033+a102);
  a107=(a107*a064);
  a033=(a033+a107);
  if (res[1]!=0) res[1][2]=a033;
  a004=(a004*a027);
  a026=(a026*a046);
  a004=(a004+a026);
  a024=(a024*a047);
  a004=(a004+a024);
  a022=(a022*a019);
  a004=(a004+a022);
  a021=(a021*a064);
  a004=(a004+a021);
  if (res[1]!=0) res[1][3]=a004;
  a004=(a070*a035);
  a021=(a081*a072);
  a004=(a004+a021);
  a021=(a094*a067);
  a004=(a004+a021);
  a021=(a099*a028);
  a004=(a004+a021);
  a021=(a004*a070);
  a061=(a020*a061);
  a058=(a056*a058);
  a061=(a061-a058);
  a003=(a063*a003);
  a061=(a061+a003);
  a077=(a008*a077);
  a061=(a061-a077);
  a076=(a059*a076);
  a061=(a061+a076);
  a076=(a070*a061);
  a077=(a081*a078);
  a076=(a076+a077);
  a077=(a094*a083);
  a076=(a076+a077);
  a077=(a099*a097);
  a076=(a076+a077);
  a077=(a076*a081);
  a021=(a021+a077);
  a077=(a020*a087);
  a003=(a056*a086);
  a077=(a077-a003);
  a003=(a063*a088);
  a077=(a077+a003);
  a090=(a008*a090);
  a077=(a077+a090);
  a091=(a059*a091);
  a077=(a077-a091);
  a091=(a070*a077);
  a086=(a001*a086);
  a087=(a002*a087);
  a086=(a086-a087);
  a088=(a034*a088);
  a086=(a086+a088);
  a088=(a081*a086);
  a091=(a091+a088);
  a088=(a094*a089);
  a091=(a091+a088);
  a088=(a099*a096);
  a091=(a091+a088);
  a088=(a091*a094);
  a021=(a021+a088);
  a020=(a020*a054);
  a056=(a056*a085);
  a020=(a020-a056);
  a063=(a063*a043);
  a020=(a020+a063);
  a008=(a008*a048);
  a020=(a020+a008);
  a059=(a059*a100);
  a020=(a020+a059);
  a059=(a070*a020);
  a001=(a001*a085);
  a002=(a002*a054);
  a001=(a001-a002);
  a034=(a034*a043);
  a001=(a001+a034);
  a034=(a081*a001);
  a059=(a059+a034);
  a013=(a013*a085);
  a007=(a007*a054);
  a013=(a013-a007);
  a069=(a069*a043);
  a013=(a013+a069);
  a060=(a060*a048);
  a013=(a013+a060);
  a060=(a094*a013);
  a059=(a059+a060);
  a060=(a099*a045);
  a059=(a059+a060);
  a060=(a059*a099);
  a021=(a021+a060);
  if (res[2]!=0) res[2][0]=a021;
  a035=(a068*a035);
  a072=(a037*a072);
  a035=(a035+a072);
  a067=(a039*a067);
  a035=(a035+a067);
  a028=(a095*a028);
  a035=(a035+a028);
  a028=(a035*a070);
  a061=(a068*a061);
  a078=(a037*a078);
  a061=(a061+a078);
  a083=(a039*a083);
  a061=(a061+a083);
  a097=(a095*a097);
  a061=(a061+a097);
  a081=(a061*a081);
  a028=(a028+a081);
  a077=(a068*a077);
  a086=(a037*a086);
  a077=(a077+a086);
  a089=(a039*a089);
  a077=(a077+a089);
  a096=(a095*a096);
  a077=(a077+a096);
  a094=(a077*a094);
  a028=(a028+a094);
  a020=(a068*a020);
  a001=(a037*a001);
  a020=(a020+a001);
  a013=(a039*a013);
  a020=(a020+a013);
  a045=(a095*a045);
  a020=(a020+a045);
  a099=(a020*a099);
  a028=(a028+a099);
  if (res[2]!=0) res[2][1]=a028;
  a004=(a004*a068);
  a076=(a076*a037);
  a004=(a004+a076);
  a091=(a091*a039);
  a004=(a004+a091);
  a059=(a059*a095);
  a004=(a004+a059);
  if (res[2]!=0) res[2][2]=a004;
  a035=(a035*a068);
  a061=(a061*a037);
  a035=(a035+a061);
  a077=(a077*a039);
  a035=(a035+a077);
  a020=(a020*a095);
  a035=(a035+a020);
  if (res[2]!=0) res[2][3]=a035;
  if (res[3]!=0) res[3][0]=a052;
  a050=(-a050);
  if (res[3]!=0) res[3][1]=a050;
  if (res[3]!=0) res[3][2]=a050;
  if (res[3]!=0) res[3][3]=a049;
  a070=(-a070);
  if (res[4]!=0) res[4][0]=a070;
  a068=(-a068);
  if (res[4]!=0) res[4][1]=a068;
  a080=(a080/a079);
  a055=casadi_fmin(a055,a080);
  a093=(a093/a092);
  a055=casadi_fmin(a055,a093);
  a014=(a014/a075);
  a055=casadi_fmin(a055,a014);
  if (res[5]!=0) res[5][0]=a055;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na2_metric_forms_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_metric_forms_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_metric_forms_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_metric_forms_n_in(void) { return 11;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_metric_forms_n_out(void) { return 6;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na2_metric_forms_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_metric_forms_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    case 2: return "contact_link";
    case 3: return "side";
    case 4: return "object_mass";
    case 5: return "object_inertia";
    case 6: return "q_obj";
    case 7: return "rho";
    case 8: return "wheel_offset";
    case 9: return "free";
    case 10: return "regularization";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_metric_forms_name_out(casadi_int i) {
  switch (i) {
    case 0: return "omega_tau";
    case 1: return "xi_tau";
    case 2: return "lambda_form_tau";
    case 3: return "input_metric";
    case 4: return "contact_from_tau";
    case 5: return "pivot_ratio";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_metric_forms_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    case 5: return casadi_s3;
    case 6: return casadi_s2;
    case 7: return casadi_s4;
    case 8: return casadi_s2;
    case 9: return casadi_s5;
    case 10: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_metric_forms_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s6;
    case 1: return casadi_s6;
    case 2: return casadi_s6;
    case 3: return casadi_s6;
    case 4: return casadi_s7;
    case 5: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 11;
  if (sz_res) *sz_res = 6;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 11*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 6*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Batched drivers rendered from derive/templates/batch.c.j2.
 * snakecg's counterpart of CasADi's Function.map(n, "serial"): one loop in C over n samples,
 * reading inputs in place (input k of sample i at arg[k] + i * stride[k]; stride 0 broadcasts)
 * and writing dense column-major outputs contiguously (output k of sample i at
 * res[k] + i * nnz_out(k)). Returns 0 on success, the failing sample + 1 otherwise, -1 when out of memory.
 * ---------------------------------------------------------------------------------------- */
#include <stdlib.h>

CASADI_SYMBOL_EXPORT int snakecg_na2_batch_metric_forms(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[11];
  casadi_real* r[6];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 110);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 11; ++k) a[k] = 0;
  for (k = 0; k < 6; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    a[6] = arg[6] + i * stride[6];
    a[7] = arg[7] + i * stride[7];
    a[8] = arg[8] + i * stride[8];
    a[9] = arg[9] + i * stride[9];
    a[10] = arg[10] + i * stride[10];
    r[0] = res[0] + i * 4;
    r[1] = res[1] + i * 4;
    r[2] = res[2] + i * 4;
    r[3] = res[3] + i * 4;
    r[4] = res[4] + i * 2;
    r[5] = res[5] + i * 1;
    if (snakecg_na2_metric_forms(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
