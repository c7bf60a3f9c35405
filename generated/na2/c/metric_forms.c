/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for metric_forms() of
 * generated/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 92aa81f73b9d7ff69afc31c561cda203208b6d2de4fc2c5b6871a20f60622a96
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
  a000=arg[0]? arg[0][2] : 0;
  a001=arg[2]? arg[2][0] : 0;
  a002=(a000*a001);
  a003=arg[0]? arg[0][3] : 0;
  a003=(a003+a000);
  a004=arg[2]? arg[2][1] : 0;
  a005=(a003*a004);
  a002=(a002+a005);
  a005=arg[0]? arg[0][4] : 0;
  a005=(a003+a005);
  a006=arg[2]? arg[2][2] : 0;
  a007=(a005*a006);
  a002=(a002+a007);
  a007=sin(a002);
  a008=arg[3]? arg[3][0] : 0;
  a009=(a007*a008);
  a010=arg[4]? arg[4][0] : 0;
  a011=(a009/a010);
  a012=arg[9]? arg[9][0] : 0;
  a013=(a001+a004);
  a013=(a013+a006);
  a014=(a009*a013);
  a015=arg[1]? arg[1][15] : 0;
  a016=sin(a005);
  a017=(a015*a016);
  a018=arg[1]? arg[1][14] : 0;
  a019=sin(a003);
  a020=(a018*a019);
  a020=(a017+a020);
  a021=arg[1]? arg[1][13] : 0;
  a022=sin(a000);
  a023=(a021*a022);
  a023=(a020+a023);
  a024=arg[1]? arg[1][12] : 0;
  a025=(a023/a024);
  a000=cos(a000);
  a005=cos(a005);
  a026=(a000*a005);
  a027=(a022*a016);
  a026=(a026+a027);
  a027=arg[1]? arg[1][18] : 0;
  a026=(a026*a027);
  a003=cos(a003);
  a027=(a003*a005);
  a028=(a019*a016);
  a027=(a027+a028);
  a028=arg[1]? arg[1][20] : 0;
  a027=(a027*a028);
  a028=arg[1]? arg[1][24] : 0;
  a029=(a027+a028);
  a030=(a026+a029);
  a031=(a017/a024);
  a032=(a031*a025);
  a032=(a032*a024);
  a032=(a030-a032);
  a015=(a015*a005);
  a033=(a015/a024);
  a018=(a018*a003);
  a018=(a015+a018);
  a021=(a021*a000);
  a021=(a018+a021);
  a034=(a021/a024);
  a035=(a033*a034);
  a035=(a035*a024);
  a032=(a032-a035);
  a035=(a000*a003);
  a036=(a022*a019);
  a035=(a035+a036);
  a036=arg[1]? arg[1][17] : 0;
  a035=(a035*a036);
  a036=arg[1]? arg[1][23] : 0;
  a027=(a027+a036);
  a036=(a035+a027);
  a036=(a036+a030);
  a035=(a035+a026);
  a026=arg[1]? arg[1][22] : 0;
  a026=(a035+a026);
  a036=(a036+a026);
  a026=casadi_sq(a025);
  a026=(a026*a024);
  a026=(a036-a026);
  a037=casadi_sq(a034);
  a037=(a037*a024);
  a026=(a026-a037);
  a032=(a032/a026);
  a037=(a020/a024);
  a038=(a031*a037);
  a038=(a038*a024);
  a038=(a029-a038);
  a039=(a018/a024);
  a040=(a033*a039);
  a040=(a040*a024);
  a038=(a038-a040);
  a027=(a027+a029);
  a035=(a027+a035);
  a040=(a037*a025);
  a040=(a040*a024);
  a040=(a035-a040);
  a041=(a039*a034);
  a041=(a041*a024);
  a040=(a040-a041);
  a040=(a040/a026);
  a041=(a032*a040);
  a041=(a041*a026);
  a038=(a038-a041);
  a041=casadi_sq(a037);
  a041=(a041*a024);
  a041=(a027-a041);
  a042=casadi_sq(a039);
  a042=(a042*a024);
  a041=(a041-a042);
  a042=casadi_sq(a040);
  a042=(a042*a026);
  a041=(a041-a042);
  a038=(a038/a041);
  a042=casadi_sq(a031);
  a042=(a042*a024);
  a042=(a028-a042);
  a043=casadi_sq(a033);
  a043=(a043*a024);
  a042=(a042-a043);
  a043=casadi_sq(a032);
  a043=(a043*a026);
  a042=(a042-a043);
  a043=casadi_sq(a038);
  a043=(a043*a041);
  a042=(a042-a043);
  a043=(a038/a042);
  a044=(a032*a043);
  a045=(1./a041);
  a046=(a038*a043);
  a045=(a045+a046);
  a046=(a040*a045);
  a044=(a044-a046);
  a046=(a025*a044);
  a047=(a037*a045);
  a046=(a046+a047);
  a047=(a031*a043);
  a046=(a046-a047);
  a047=(a014*a046);
  a002=cos(a002);
  a048=(a002*a008);
  a049=(a048*a013);
  a050=(a033*a043);
  a051=(a034*a044);
  a052=(a039*a045);
  a051=(a051+a052);
  a050=(a050-a051);
  a051=(a049*a050);
  a047=(a047-a051);
  a051=arg[0]? arg[0][1] : 0;
  a052=arg[1]? arg[1][3] : 0;
  a053=arg[1]? arg[1][9] : 0;
  a052=(a052-a053);
  a054=(a052*a022);
  a054=(a051+a054);
  a055=arg[1]? arg[1][10] : 0;
  a056=(a019*a055);
  a057=(a054+a056);
  a058=(a051-a057);
  a059=(a004*a058);
  a060=arg[1]? arg[1][4] : 0;
  a060=(a060-a055);
  a061=(a060*a019);
  a061=(a057+a061);
  a062=arg[1]? arg[1][11] : 0;
  a063=(a016*a062);
  a061=(a061+a063);
  a064=(a051-a061);
  a065=(a006*a064);
  a059=(a059+a065);
  a059=(a009*a059);
  a065=arg[0]? arg[0][0] : 0;
  a052=(a000*a052);
  a052=(a065+a052);
  a066=(a003*a055);
  a067=(a052+a066);
  a068=(a067-a065);
  a069=(a004*a068);
  a060=(a003*a060);
  a060=(a067+a060);
  a070=(a005*a062);
  a060=(a060+a070);
  a071=(a060-a065);
  a072=(a006*a071);
  a069=(a069+a072);
  a069=(a048*a069);
  a059=(a059-a069);
  a053=(a053*a001);
  a055=(a055*a004);
  a053=(a053+a055);
  a062=(a062*a006);
  a053=(a053+a062);
  a062=(a008*a053);
  a055=arg[6]? arg[6][2] : 0;
  a069=cos(a055);
  a072=arg[7]? arg[7][1] : 0;
  a073=(a069*a072);
  a055=sin(a055);
  a074=arg[7]? arg[7][0] : 0;
  a075=(a055*a074);
  a073=(a073+a075);
  a075=arg[6]? arg[6][1] : 0;
  a075=(a073+a075);
  a007=(a007*a053);
  a075=(a075+a007);
  a051=(a051*a001);
  a057=(a057*a004);
  a051=(a051+a057);
  a057=(a061*a006);
  a051=(a051+a057);
  a075=(a075-a051);
  a075=(a009*a075);
  a062=(a062-a075);
  a069=(a069*a074);
  a055=(a055*a072);
  a069=(a069-a055);
  a055=arg[6]? arg[6][0] : 0;
  a055=(a069+a055);
  a053=(a002*a053);
  a055=(a055+a053);
  a065=(a065*a001);
  a067=(a067*a004);
  a065=(a065+a067);
  a067=(a060*a006);
  a065=(a065+a067);
  a055=(a055-a065);
  a055=(a048*a055);
  a062=(a062-a055);
  a013=(a062*a013);
  a059=(a059+a013);
  a013=(a059*a044);
  a047=(a047+a013);
  a054=(a054-a061);
  a061=(a006*a054);
  a013=(a004*a056);
  a061=(a061-a013);
  a061=(a009*a061);
  a013=(a004*a066);
  a060=(a060-a052);
  a052=(a006*a060);
  a013=(a013+a052);
  a013=(a048*a013);
  a061=(a061-a013);
  a004=(a004+a006);
  a004=(a062*a004);
  a061=(a061+a004);
  a004=(a061*a045);
  a047=(a047+a004);
  a062=(a062*a006);
  a004=(a006*a063);
  a004=(a009*a004);
  a006=(a006*a070);
  a006=(a048*a006);
  a004=(a004+a006);
  a062=(a062-a004);
  a004=(a062*a043);
  a047=(a047-a004);
  a047=(a012*a047);
  a004=(a014/a024);
  a006=(a025*a014);
  a006=(a059+a006);
  a013=(a034*a049);
  a006=(a006+a013);
  a013=(a006/a026);
  a052=(a037*a014);
  a052=(a061+a052);
  a055=(a039*a049);
  a052=(a052+a055);
  a055=(a040*a006);
  a052=(a052-a055);
  a055=(a052/a041);
  a065=(a031*a014);
  a065=(a062+a065);
  a067=(a033*a049);
  a065=(a065+a067);
  a006=(a032*a006);
  a065=(a065-a006);
  a052=(a038*a052);
  a065=(a065-a052);
  a065=(a065/a042);
  a052=(a038*a065);
  a055=(a055-a052);
  a052=(a040*a055);
  a013=(a013-a052);
  a052=(a032*a065);
  a013=(a013-a052);
  a052=(a025*a013);
  a004=(a004+a052);
  a052=(a037*a055);
  a004=(a004+a052);
  a052=(a031*a065);
  a004=(a004+a052);
  a052=(a014*a004);
  a006=(a049/a024);
  a067=(a034*a013);
  a006=(a006+a067);
  a067=(a039*a055);
  a006=(a006+a067);
  a067=(a033*a065);
  a006=(a006+a067);
  a067=(a049*a006);
  a052=(a052+a067);
  a067=(a059*a013);
  a052=(a052+a067);
  a067=(a061*a055);
  a052=(a052+a067);
  a067=(a062*a065);
  a052=(a052+a067);
  a067=(a009*a011);
  a001=(a048/a010);
  a048=(a048*a001);
  a067=(a067+a048);
  a002=(a002*a069);
  a002=(a002*a008);
  a009=(a009*a073);
  a002=(a002+a009);
  a009=arg[5]? arg[5][0] : 0;
  a073=(a002/a009);
  a002=(a002*a073);
  a067=(a067+a002);
  a052=(a052+a067);
  a067=(a012*a052);
  a067=(a067*a012);
  a002=1.;
  a008=(a002-a012);
  a067=(a067+a008);
  a008=arg[10]? arg[10][0] : 0;
  a069=(a008*a012);
  a067=(a067+a069);
  a069=(a047/a067);
  a048=arg[9]? arg[9][1] : 0;
  a053=arg[8]? arg[8][0] : 0;
  a072=(a053*a013);
  a074=(a022*a004);
  a075=(a000*a006);
  a074=(a074+a075);
  a072=(a072-a074);
  a074=(a048*a072);
  a074=(a074*a012);
  a074=(a074/a067);
  a075=(a000*a050);
  a051=(a022*a046);
  a075=(a075-a051);
  a051=(a053*a044);
  a075=(a075+a051);
  a075=(a048*a075);
  a051=(a074*a047);
  a075=(a075-a051);
  a051=(a000/a024);
  a057=(a025*a022);
  a057=(a053-a057);
  a007=(a034*a000);
  a057=(a057-a007);
  a007=(a057/a026);
  a076=(a037*a022);
  a077=(a039*a000);
  a076=(a076+a077);
  a077=(a040*a057);
  a076=(a076+a077);
  a077=(a076/a041);
  a076=(a038*a076);
  a078=(a031*a022);
  a079=(a033*a000);
  a078=(a078+a079);
  a057=(a032*a057);
  a078=(a078+a057);
  a076=(a076-a078);
  a076=(a076/a042);
  a078=(a038*a076);
  a077=(a077+a078);
  a078=(a040*a077);
  a007=(a007+a078);
  a078=(a032*a076);
  a007=(a007-a078);
  a078=(a034*a007);
  a051=(a051-a078);
  a078=(a039*a077);
  a051=(a051+a078);
  a078=(a033*a076);
  a051=(a051-a078);
  a078=(a000*a051);
  a057=(a025*a007);
  a079=(a022/a024);
  a057=(a057-a079);
  a079=(a037*a077);
  a057=(a057-a079);
  a079=(a031*a076);
  a057=(a057+a079);
  a079=(a022*a057);
  a078=(a078-a079);
  a079=(a053*a007);
  a078=(a078+a079);
  a079=(a048*a078);
  a079=(a079*a048);
  a080=(a002-a048);
  a079=(a079+a080);
  a080=(a008*a048);
  a079=(a079+a080);
  a080=casadi_sq(a074);
  a080=(a080*a067);
  a080=(a079-a080);
  a081=(a075/a080);
  a082=arg[9]? arg[9][2] : 0;
  a083=(a003*a051);
  a084=(a019*a057);
  a083=(a083-a084);
  a068=(a003*a068);
  a058=(a019*a058);
  a068=(a068-a058);
  a058=arg[8]? arg[8][1] : 0;
  a068=(a068+a058);
  a084=(a068*a007);
  a083=(a083+a084);
  a056=(a019*a056);
  a066=(a003*a066);
  a056=(a056+a066);
  a056=(a056+a058);
  a058=(a056*a077);
  a083=(a083-a058);
  a058=(a082*a083);
  a058=(a058*a048);
  a066=(a068*a013);
  a084=(a019*a004);
  a085=(a003*a006);
  a084=(a084+a085);
  a066=(a066-a084);
  a084=(a056*a055);
  a066=(a066+a084);
  a084=(a082*a066);
  a084=(a084*a012);
  a084=(a084/a067);
  a085=(a084*a074);
  a085=(a085*a067);
  a058=(a058-a085);
  a058=(a058/a080);
  a085=(a003*a050);
  a086=(a019*a046);
  a085=(a085-a086);
  a086=(a068*a044);
  a085=(a085+a086);
  a086=(a056*a045);
  a085=(a085+a086);
  a085=(a082*a085);
  a086=(a084*a047);
  a085=(a085-a086);
  a086=(a058*a075);
  a085=(a085-a086);
  a086=(a003/a024);
  a087=(a025*a019);
  a087=(a068-a087);
  a088=(a034*a003);
  a087=(a087-a088);
  a088=(a087/a026);
  a089=(a037*a019);
  a089=(a056-a089);
  a090=(a039*a003);
  a089=(a089-a090);
  a090=(a040*a087);
  a089=(a089-a090);
  a090=(a089/a041);
  a091=(a031*a019);
  a092=(a033*a003);
  a091=(a091+a092);
  a087=(a032*a087);
  a091=(a091+a087);
  a089=(a038*a089);
  a091=(a091+a089);
  a091=(a091/a042);
  a089=(a038*a091);
  a090=(a090+a089);
  a089=(a040*a090);
  a088=(a088-a089);
  a089=(a032*a091);
  a088=(a088+a089);
  a089=(a034*a088);
  a086=(a086-a089);
  a089=(a039*a090);
  a086=(a086-a089);
  a089=(a033*a091);
  a086=(a086+a089);
  a089=(a003*a086);
  a087=(a025*a088);
  a092=(a019/a024);
  a087=(a087-a092);
  a092=(a037*a090);
  a087=(a087+a092);
  a092=(a031*a091);
  a087=(a087-a092);
  a092=(a019*a087);
  a089=(a089-a092);
  a092=(a068*a088);
  a089=(a089+a092);
  a092=(a056*a090);
  a089=(a089+a092);
  a092=(a082*a089);
  a092=(a092*a082);
  a093=(a002-a082);
  a092=(a092+a093);
  a093=(a008*a082);
  a092=(a092+a093);
  a093=casadi_sq(a084);
  a093=(a093*a067);
  a093=(a092-a093);
  a094=casadi_sq(a058);
  a094=(a094*a080);
  a093=(a093-a094);
  a094=(a085/a093);
  a095=arg[9]? arg[9][3] : 0;
  a096=(a005*a086);
  a097=(a016*a087);
  a096=(a096-a097);
  a071=(a005*a071);
  a064=(a016*a064);
  a071=(a071-a064);
  a064=arg[8]? arg[8][2] : 0;
  a071=(a071+a064);
  a097=(a071*a088);
  a096=(a096+a097);
  a060=(a005*a060);
  a054=(a016*a054);
  a060=(a060-a054);
  a060=(a060+a064);
  a054=(a060*a090);
  a096=(a096+a054);
  a063=(a016*a063);
  a070=(a005*a070);
  a063=(a063+a070);
  a063=(a063+a064);
  a064=(a063*a091);
  a096=(a096-a064);
  a064=(a095*a096);
  a064=(a064*a082);
  a070=(a071*a013);
  a054=(a016*a004);
  a097=(a005*a006);
  a054=(a054+a097);
  a070=(a070-a054);
  a054=(a060*a055);
  a070=(a070+a054);
  a054=(a063*a065);
  a070=(a070+a054);
  a054=(a095*a070);
  a054=(a054*a012);
  a054=(a054/a067);
  a097=(a054*a084);
  a097=(a097*a067);
  a064=(a064-a097);
  a097=(a005*a051);
  a098=(a016*a057);
  a097=(a097-a098);
  a098=(a071*a007);
  a097=(a097+a098);
  a098=(a060*a077);
  a097=(a097-a098);
  a098=(a063*a076);
  a097=(a097+a098);
  a098=(a095*a097);
  a098=(a098*a048);
  a099=(a054*a074);
  a099=(a099*a067);
  a098=(a098-a099);
  a098=(a098/a080);
  a099=(a098*a058);
  a099=(a099*a080);
  a064=(a064-a099);
  a064=(a064/a093);
  a099=(a005*a050);
  a100=(a016*a046);
  a099=(a099-a100);
  a100=(a071*a044);
  a099=(a099+a100);
  a100=(a060*a045);
  a099=(a099+a100);
  a100=(a063*a043);
  a099=(a099-a100);
  a099=(a095*a099);
  a047=(a054*a047);
  a099=(a099-a047);
  a075=(a098*a075);
  a099=(a099-a075);
  a085=(a064*a085);
  a099=(a099-a085);
  a085=(a005/a024);
  a075=(a025*a016);
  a075=(a071-a075);
  a047=(a034*a005);
  a075=(a075-a047);
  a026=(a075/a026);
  a047=(a037*a016);
  a047=(a060-a047);
  a100=(a039*a005);
  a047=(a047-a100);
  a100=(a040*a075);
  a047=(a047-a100);
  a041=(a047/a041);
  a100=(a031*a016);
  a100=(a063-a100);
  a101=(a033*a005);
  a100=(a100-a101);
  a075=(a032*a075);
  a100=(a100-a075);
  a047=(a038*a047);
  a100=(a100-a047);
  a100=(a100/a042);
  a038=(a038*a100);
  a041=(a041-a038);
  a038=(a040*a041);
  a026=(a026-a038);
  a038=(a032*a100);
  a026=(a026-a038);
  a038=(a034*a026);
  a085=(a085-a038);
  a038=(a039*a041);
  a085=(a085-a038);
  a038=(a033*a100);
  a085=(a085-a038);
  a038=(a005*a085);
  a047=(a025*a026);
  a075=(a016/a024);
  a047=(a047-a075);
  a075=(a037*a041);
  a047=(a047+a075);
  a075=(a031*a100);
  a047=(a047+a075);
  a075=(a016*a047);
  a038=(a038-a075);
  a075=(a071*a026);
  a038=(a038+a075);
  a075=(a060*a041);
  a038=(a038+a075);
  a075=(a063*a100);
  a038=(a038+a075);
  a075=(a095*a038);
  a075=(a075*a095);
  a101=(a002-a095);
  a075=(a075+a101);
  a008=(a008*a095);
  a075=(a075+a008);
  a008=casadi_sq(a054);
  a008=(a008*a067);
  a008=(a075-a008);
  a101=casadi_sq(a098);
  a101=(a101*a080);
  a008=(a008-a101);
  a101=casadi_sq(a064);
  a101=(a101*a093);
  a008=(a008-a101);
  a099=(a099/a008);
  a101=(a064*a099);
  a094=(a094-a101);
  a101=(a058*a094);
  a081=(a081-a101);
  a101=(a098*a099);
  a081=(a081-a101);
  a101=(a074*a081);
  a069=(a069-a101);
  a101=(a084*a094);
  a069=(a069-a101);
  a101=(a054*a099);
  a069=(a069-a101);
  a101=(a011*a069);
  a102=(a101*a010);
  a103=(a102*a101);
  a104=(a001*a069);
  a105=(a104*a010);
  a106=(a105*a104);
  a103=(a103+a106);
  a106=(a073*a069);
  a107=(a106*a009);
  a108=(a107*a106);
  a103=(a103+a108);
  if (res[0]!=0) res[0][0]=a103;
  a040=(a040*a043);
  a032=(a032/a042);
  a040=(a040-a032);
  a025=(a025*a040);
  a037=(a037*a043);
  a025=(a025-a037);
  a031=(a031/a042);
  a025=(a025+a031);
  a031=(a014*a025);
  a039=(a039*a043);
  a034=(a034*a040);
  a039=(a039-a034);
  a033=(a033/a042);
  a039=(a039-a033);
  a033=(a049*a039);
  a031=(a031-a033);
  a033=(a059*a040);
  a031=(a031+a033);
  a033=(a061*a043);
  a031=(a031-a033);
  a033=(a062/a042);
  a031=(a031+a033);
  a012=(a012*a031);
  a067=(a012/a067);
  a031=(a000*a039);
  a033=(a022*a025);
  a031=(a031-a033);
  a033=(a053*a040);
  a031=(a031+a033);
  a048=(a048*a031);
  a031=(a074*a012);
  a048=(a048-a031);
  a031=(a048/a080);
  a033=(a003*a039);
  a034=(a019*a025);
  a033=(a033-a034);
  a034=(a068*a040);
  a033=(a033+a034);
  a034=(a056*a043);
  a033=(a033-a034);
  a082=(a082*a033);
  a033=(a084*a012);
  a082=(a082-a033);
  a033=(a058*a048);
  a082=(a082-a033);
  a033=(a082/a093);
  a005=(a005*a039);
  a016=(a016*a025);
  a005=(a005-a016);
  a071=(a071*a040);
  a005=(a005+a071);
  a060=(a060*a043);
  a005=(a005-a060);
  a063=(a063/a042);
  a005=(a005+a063);
  a095=(a095*a005);
  a012=(a054*a012);
  a095=(a095-a012);
  a048=(a098*a048);
  a095=(a095-a048);
  a082=(a064*a082);
  a095=(a095-a082);
  a095=(a095/a008);
  a064=(a064*a095);
  a033=(a033-a064);
  a058=(a058*a033);
  a031=(a031-a058);
  a098=(a098*a095);
  a031=(a031-a098);
  a074=(a074*a031);
  a067=(a067-a074);
  a084=(a084*a033);
  a067=(a067-a084);
  a054=(a054*a095);
  a067=(a067-a054);
  a011=(a011*a067);
  a054=(a011*a010);
  a101=(a054*a101);
  a001=(a001*a067);
  a010=(a001*a010);
  a104=(a010*a104);
  a101=(a101+a104);
  a073=(a073*a067);
  a009=(a073*a009);
  a106=(a009*a106);
  a101=(a101+a106);
  if (res[0]!=0) res[0][1]=a101;
  a102=(a102*a011);
  a105=(a105*a001);
  a102=(a102+a105);
  a107=(a107*a073);
  a102=(a102+a107);
  if (res[0]!=0) res[0][2]=a102;
  a054=(a054*a011);
  a010=(a010*a001);
  a054=(a054+a010);
  a009=(a009*a073);
  a054=(a054+a009);
  if (res[0]!=0) res[0][3]=a054;
  a054=(a004*a069);
  a009=(a057*a081);
  a054=(a054+a009);
  a009=(a087*a094);
  a054=(a054+a009);
  a009=(a047*a099);
  a054=(a054+a009);
  a046=(a046-a054);
  a054=(a046*a024);
  a009=(a013*a069);
  a073=(a007*a081);
  a009=(a009+a073);
  a073=(a088*a094);
  a009=(a009+a073);
  a073=(a026*a099);
  a009=(a009+a073);
  a044=(a044-a009);
  a009=(a044*a023);
  a054=(a054-a009);
  a009=(a077*a081);
  a073=(a055*a069);
  a009=(a009-a073);
  a073=(a090*a094);
  a009=(a009-a073);
  a073=(a041*a099);
  a009=(a009-a073);
  a009=(a045+a009);
  a073=(a009*a020);
  a054=(a054-a073);
  a073=(a091*a094);
  a010=(a065*a069);
  a001=(a076*a081);
  a010=(a010+a001);
  a073=(a073-a010);
  a010=(a100*a099);
  a073=(a073-a010);
  a073=(a073-a043);
  a010=(a073*a017);
  a054=(a054-a010);
  a010=(a054*a046);
  a001=(a006*a069);
  a011=(a051*a081);
  a001=(a001-a011);
  a011=(a086*a094);
  a001=(a001-a011);
  a011=(a085*a099);
  a001=(a001-a011);
  a050=(a050+a001);
  a001=(a050*a024);
  a011=(a044*a021);
  a001=(a001+a011);
  a011=(a009*a018);
  a001=(a001+a011);
  a011=(a073*a015);
  a001=(a001+a011);
  a011=(a001*a050);
  a010=(a010+a011);
  a011=(a050*a021);
  a102=(a046*a023);
  a011=(a011-a102);
  a102=(a044*a036);
  a011=(a011+a102);
  a102=(a009*a035);
  a011=(a011+a102);
  a102=(a073*a030);
  a011=(a011+a102);
  a102=(a011*a044);
  a010=(a010+a102);
  a102=(a050*a018);
  a107=(a046*a020);
  a102=(a102-a107);
  a107=(a044*a035);
  a102=(a102+a107);
  a107=(a009*a027);
  a102=(a102+a107);
  a107=(a073*a029);
  a102=(a102+a107);
  a107=(a102*a009);
  a010=(a010+a107);
  a107=(a050*a015);
  a105=(a046*a017);
  a107=(a107-a105);
  a105=(a044*a030);
  a107=(a107+a105);
  a105=(a009*a029);
  a107=(a107+a105);
  a105=(a073*a028);
  a107=(a107+a105);
  a105=(a107*a073);
  a010=(a010+a105);
  if (res[1]!=0) res[1][0]=a010;
  a004=(a004*a067);
  a010=(a057*a031);
  a004=(a004+a010);
  a010=(a087*a033);
  a004=(a004+a010);
  a010=(a047*a095);
  a004=(a004+a010);
  a025=(a025-a004);
  a004=(a025*a024);
  a013=(a013*a067);
  a010=(a007*a031);
  a013=(a013+a010);
  a010=(a088*a033);
  a013=(a013+a010);
  a010=(a026*a095);
  a013=(a013+a010);
  a040=(a040-a013);
  a013=(a040*a023);
  a004=(a004-a013);
  a013=(a077*a031);
  a055=(a055*a067);
  a013=(a013-a055);
  a055=(a090*a033);
  a013=(a013-a055);
  a055=(a041*a095);
  a013=(a013-a055);
  a013=(a013-a043);
  a055=(a013*a020);
  a004=(a004-a055);
  a042=(1./a042);
  a055=(a091*a033);
  a065=(a065*a067);
  a010=(a076*a031);
  a065=(a065+a010);
  a055=(a055-a065);
  a065=(a100*a095);
  a055=(a055-a065);
  a055=(a042+a055);
  a065=(a055*a017);
  a004=(a004-a065);
  a046=(a004*a046);
  a006=(a006*a067);
  a065=(a051*a031);
  a006=(a006-a065);
  a065=(a086*a033);
  a006=(a006-a065);
  a065=(a085*a095);
  a006=(a006-a065);
  a039=(a039+a006);
  a024=(a039*a024);
  a006=(a040*a021);
  a024=(a024+a006);
  a006=(a013*a018);
  a024=(a024+a006);
  a006=(a055*a015);
  a024=(a024+a006);
  a050=(a024*a050);
  a046=(a046+a050);
  a021=(a039*a021);
  a023=(a025*a023);
  a021=(a021-a023);
  a036=(a040*a036);
  a021=(a021+a036);
  a036=(a013*a035);
  a021=(a021+a036);
  a036=(a055*a030);
  a021=(a021+a036);
  a044=(a021*a044);
  a046=(a046+a044);
  a018=(a039*a018);
  a020=(a025*a020);
  a018=(a018-a020);
  a035=(a040*a035);
  a018=(a018+a035);
  a027=(a013*a027);
  a018=(a018+a027);
  a027=(a055*a029);
  a018=(a018+a027);
  a009=(a018*a009);
  a046=(a046+a009);
  a015=(a039*a015);
  a017=(a025*a017);
  a015=(a015-a017);
  a030=(a040*a030);
  a015=(a015+a030);
  a029=(a013*a029);
  a015=(a015+a029);
  a028=(a055*a028);
  a015=(a015+a028);
  a073=(a015*a073);
  a046=(a046+a073);
  if (res[1]!=0) res[1][1]=a046;
  a054=(a054*a025);
  a001=(a001*a039);
  a054=(a054+a001);
  a011=(a011*a040);
  a054=(a054+a011);
  a102=(a102*a013);
  a054=(a054+a102);
  a107=(a107*a055);
  a054=(a054+a107);
  if (res[1]!=0) res[1][2]=a054;
  a004=(a004*a025);
  a024=(a024*a039);
  a004=(a004+a024);
  a021=(a021*a040);
  a004=(a004+a021);
  a018=(a018*a013);
  a004=(a004+a018);
  a015=(a015*a055);
  a004=(a004+a015);
  if (res[1]!=0) res[1][3]=a004;
  a004=(a069*a052);
  a015=(a081*a072);
  a004=(a004+a015);
  a015=(a094*a066);
  a004=(a004+a015);
  a015=(a099*a070);
  a004=(a004+a015);
  a015=(a004*a069);
  a057=(a014*a057);
  a051=(a049*a051);
  a057=(a057-a051);
  a007=(a059*a007);
  a057=(a057+a007);
  a077=(a061*a077);
  a057=(a057-a077);
  a076=(a062*a076);
  a057=(a057+a076);
  a076=(a069*a057);
  a077=(a081*a078);
  a076=(a076+a077);
  a077=(a094*a083);
  a076=(a076+a077);
  a077=(a099*a097);
  a076=(a076+a077);
  a077=(a076*a081);
  a015=(a015+a077);
  a077=(a014*a087);
  a007=(a049*a086);
  a077=(a077-a007);
  a007=(a059*a088);
  a077=(a077+a007);
  a090=(a061*a090);
  a077=(a077+a090);
  a091=(a062*a091);
  a077=(a077-a091);
  a091=(a069*a077);
  a086=(a000*a086);
  a087=(a022*a087);
  a086=(a086-a087);
  a088=(a053*a088);
  a086=(a086+a088);
  a088=(a081*a086);
  a091=(a091+a088);
  a088=(a094*a089);
  a091=(a091+a088);
  a088=(a099*a096);
  a091=(a091+a088);
  a088=(a091*a094);
  a015=(a015+a088);
  a014=(a014*a047);
  a049=(a049*a085);
  a014=(a014-a049);
  a059=(a059*a026);
  a014=(a014+a059);
  a061=(a061*a041);
  a014=(a014+a061);
  a062=(a062*a100);
  a014=(a014+a062);
  a062=(a069*a014);
  a000=(a000*a085);
  a022=(a022*a047);
  a000=(a000-a022);
  a053=(a053*a026);
  a000=(a000+a053);
  a053=(a081*a000);
  a062=(a062+a053);
  a003=(a003*a085);
  a019=(a019*a047);
  a003=(a003-a019);
  a068=(a068*a026);
  a003=(a003+a068);
  a056=(a056*a041);
  a003=(a003+a056);
  a056=(a094*a003);
  a062=(a062+a056);
  a056=(a099*a038);
  a062=(a062+a056);
  a056=(a062*a099);
  a015=(a015+a056);
  if (res[2]!=0) res[2][0]=a015;
  a052=(a067*a052);
  a072=(a031*a072);
  a052=(a052+a072);
  a066=(a033*a066);
  a052=(a052+a066);
  a070=(a095*a070);
  a052=(a052+a070);
  a070=(a052*a069);
  a057=(a067*a057);
  a078=(a031*a078);
  a057=(a057+a078);
  a083=(a033*a083);
  a057=(a057+a083);
  a097=(a095*a097);
  a057=(a057+a097);
  a081=(a057*a081);
  a070=(a070+a081);
  a077=(a067*a077);
  a086=(a031*a086);
  a077=(a077+a086);
  a089=(a033*a089);
  a077=(a077+a089);
  a096=(a095*a096);
  a077=(a077+a096);
  a094=(a077*a094);
  a070=(a070+a094);
  a014=(a067*a014);
  a000=(a031*a000);
  a014=(a014+a000);
  a003=(a033*a003);
  a014=(a014+a003);
  a038=(a095*a038);
  a014=(a014+a038);
  a099=(a014*a099);
  a070=(a070+a099);
  if (res[2]!=0) res[2][1]=a070;
  a004=(a004*a067);
  a076=(a076*a031);
  a004=(a004+a076);
  a091=(a091*a033);
  a004=(a004+a091);
  a062=(a062*a095);
  a004=(a004+a062);
  if (res[2]!=0) res[2][2]=a004;
  a052=(a052*a067);
  a057=(a057*a031);
  a052=(a052+a057);
  a077=(a077*a033);
  a052=(a052+a077);
  a014=(a014*a095);
  a052=(a052+a014);
  if (res[2]!=0) res[2][3]=a052;
  if (res[3]!=0) res[3][0]=a045;
  a043=(-a043);
  if (res[3]!=0) res[3][1]=a043;
  if (res[3]!=0) res[3][2]=a043;
  if (res[3]!=0) res[3][3]=a042;
  a069=(-a069);
  if (res[4]!=0) res[4][0]=a069;
  a067=(-a067);
  if (res[4]!=0) res[4][1]=a067;
  a080=(a080/a079);
  a002=casadi_fmin(a002,a080);
  a093=(a093/a092);
  a002=casadi_fmin(a002,a093);
  a008=(a008/a075);
  a002=casadi_fmin(a002,a008);
  if (res[5]!=0) res[5][0]=a002;
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
