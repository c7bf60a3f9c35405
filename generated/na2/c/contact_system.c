/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_system() of
 * generated/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 4e89dd687d4cbc8709e9cfd98d262e9a276cb64607f251a625473028d4ba2314
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na2_contact_system_ ## ID
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
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_s6 CASADI_PREFIX(s6)
#define casadi_s7 CASADI_PREFIX(s7)
#define casadi_s8 CASADI_PREFIX(s8)
#define casadi_s9 CASADI_PREFIX(s9)
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

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {5, 1, 1};
static const casadi_int casadi_s1[3] = {2, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {25, 1, 1};
static const casadi_int casadi_s4[3] = {1, 1, 1};
static const casadi_int casadi_s5[3] = {5, 5, 1};
static const casadi_int casadi_s6[3] = {4, 4, 1};
static const casadi_int casadi_s7[3] = {4, 1, 1};
static const casadi_int casadi_s8[3] = {5, 4, 1};
static const casadi_int casadi_s9[3] = {3, 4, 1};

/* snakecg_na2_contact_system:(q[5],v[5],tau[2],q_obj[3],v_obj[3],f_obj[3],K[25],contact_link[3],side,object_mass,object_inertia,rho[2],wheel_offset[3])->(M[5x5],delassus[4x4],b[4],qdd_free[5],a_obj_free[3],qdd_from_lam[5x4],a_obj_from_lam[3x4],gap,s) */
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
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117, a118;
  a000=arg[6]? arg[6][12] : 0;
  if (res[0]!=0) res[0][0]=a000;
  a001=0.;
  if (res[0]!=0) res[0][1]=a001;
  a002=arg[6]? arg[6][15] : 0;
  a003=arg[0]? arg[0][2] : 0;
  a004=cos(a003);
  a005=arg[0]? arg[0][3] : 0;
  a006=cos(a005);
  a007=(a004*a006);
  a008=sin(a003);
  a009=sin(a005);
  a010=(a008*a009);
  a007=(a007-a010);
  a010=arg[0]? arg[0][4] : 0;
  a011=sin(a010);
  a012=(a007*a011);
  a013=cos(a010);
  a009=(a004*a009);
  a006=(a006*a008);
  a009=(a009+a006);
  a006=(a013*a009);
  a012=(a012+a006);
  a006=(a002*a012);
  a014=arg[6]? arg[6][14] : 0;
  a015=(a014*a009);
  a015=(a006+a015);
  a016=arg[6]? arg[6][13] : 0;
  a017=(a016*a008);
  a017=(a015+a017);
  a018=(-a017);
  if (res[0]!=0) res[0][2]=a018;
  a019=(-a015);
  if (res[0]!=0) res[0][3]=a019;
  a020=(-a006);
  if (res[0]!=0) res[0][4]=a020;
  if (res[0]!=0) res[0][5]=a001;
  if (res[0]!=0) res[0][6]=a000;
  a013=(a007*a013);
  a011=(a009*a011);
  a013=(a013-a011);
  a002=(a002*a013);
  a014=(a014*a007);
  a014=(a002+a014);
  a016=(a016*a004);
  a016=(a014+a016);
  if (res[0]!=0) res[0][7]=a016;
  if (res[0]!=0) res[0][8]=a014;
  if (res[0]!=0) res[0][9]=a002;
  if (res[0]!=0) res[0][10]=a018;
  if (res[0]!=0) res[0][11]=a016;
  a018=arg[6]? arg[6][4] : 0;
  a011=(a007*a018);
  a011=(a002*a011);
  a021=(a009*a018);
  a021=(a006*a021);
  a011=(a011+a021);
  a021=arg[6]? arg[6][24] : 0;
  a022=(a011+a021);
  a011=(a022+a011);
  a023=arg[6]? arg[6][23] : 0;
  a011=(a011+a023);
  a023=arg[6]? arg[6][3] : 0;
  a024=arg[6]? arg[6][9] : 0;
  a023=(a023-a024);
  a025=(a004*a023);
  a026=(a014*a025);
  a027=(a023*a008);
  a028=(a015*a027);
  a026=(a026+a028);
  a028=(a011+a026);
  a026=(a028+a026);
  a029=arg[6]? arg[6][22] : 0;
  a026=(a026+a029);
  if (res[0]!=0) res[0][12]=a026;
  if (res[0]!=0) res[0][13]=a028;
  a029=(a002*a025);
  a030=(a006*a027);
  a029=(a029+a030);
  a029=(a022+a029);
  if (res[0]!=0) res[0][14]=a029;
  if (res[0]!=0) res[0][15]=a019;
  if (res[0]!=0) res[0][16]=a014;
  if (res[0]!=0) res[0][17]=a028;
  if (res[0]!=0) res[0][18]=a011;
  if (res[0]!=0) res[0][19]=a022;
  if (res[0]!=0) res[0][20]=a020;
  if (res[0]!=0) res[0][21]=a002;
  if (res[0]!=0) res[0][22]=a029;
  if (res[0]!=0) res[0][23]=a022;
  if (res[0]!=0) res[0][24]=a021;
  a020=arg[7]? arg[7][0] : 0;
  a019=(a003*a020);
  a005=(a005+a003);
  a003=arg[7]? arg[7][1] : 0;
  a030=(a005*a003);
  a019=(a019+a030);
  a010=(a005+a010);
  a030=arg[7]? arg[7][2] : 0;
  a031=(a010*a030);
  a019=(a019+a031);
  a031=sin(a019);
  a032=arg[8]? arg[8][0] : 0;
  a033=(a031*a032);
  a034=(a020+a003);
  a034=(a034+a030);
  a035=(a033*a034);
  a036=(a035/a000);
  a017=(a017/a000);
  a037=arg[0]? arg[0][1] : 0;
  a038=(a037+a027);
  a039=arg[6]? arg[6][10] : 0;
  a040=(a009*a039);
  a041=(a038+a040);
  a042=(a037-a041);
  a043=(a003*a042);
  a018=(a018-a039);
  a044=(a018*a009);
  a045=(a041+a044);
  a046=arg[6]? arg[6][11] : 0;
  a047=(a012*a046);
  a045=(a045+a047);
  a048=(a037-a045);
  a049=(a030*a048);
  a043=(a043+a049);
  a049=(a033*a043);
  a019=cos(a019);
  a050=(a019*a032);
  a051=arg[0]? arg[0][0] : 0;
  a052=(a051+a025);
  a053=(a007*a039);
  a054=(a052+a053);
  a055=(a054-a051);
  a056=(a003*a055);
  a057=(a007*a018);
  a058=(a054+a057);
  a059=(a013*a046);
  a058=(a058+a059);
  a060=(a058-a051);
  a061=(a030*a060);
  a056=(a056+a061);
  a061=(a050*a056);
  a049=(a049-a061);
  a024=(a024*a020);
  a061=(a039*a003);
  a024=(a024+a061);
  a061=(a046*a030);
  a024=(a024+a061);
  a061=(a032*a024);
  a062=arg[3]? arg[3][2] : 0;
  a063=cos(a062);
  a064=arg[11]? arg[11][1] : 0;
  a065=(a063*a064);
  a062=sin(a062);
  a066=arg[11]? arg[11][0] : 0;
  a067=(a062*a066);
  a065=(a065+a067);
  a067=arg[3]? arg[3][1] : 0;
  a067=(a065+a067);
  a068=(a031*a024);
  a067=(a067+a068);
  a068=(a037*a020);
  a041=(a041*a003);
  a068=(a068+a041);
  a041=(a045*a030);
  a068=(a068+a041);
  a067=(a067-a068);
  a068=(a033*a067);
  a061=(a061-a068);
  a063=(a063*a066);
  a062=(a062*a064);
  a063=(a063-a062);
  a062=arg[3]? arg[3][0] : 0;
  a062=(a063+a062);
  a024=(a019*a024);
  a062=(a062+a024);
  a020=(a051*a020);
  a054=(a054*a003);
  a020=(a020+a054);
  a054=(a058*a030);
  a020=(a020+a054);
  a062=(a062-a020);
  a020=(a050*a062);
  a061=(a061-a020);
  a020=(a061*a034);
  a049=(a049+a020);
  a020=(a017*a035);
  a020=(a049+a020);
  a016=(a016/a000);
  a054=(a050*a034);
  a024=(a016*a054);
  a020=(a020+a024);
  a024=casadi_sq(a017);
  a024=(a024*a000);
  a026=(a026-a024);
  a024=casadi_sq(a016);
  a024=(a024*a000);
  a026=(a026-a024);
  a024=(a020/a026);
  a015=(a015/a000);
  a064=(a015*a017);
  a064=(a064*a000);
  a028=(a028-a064);
  a014=(a014/a000);
  a064=(a014*a016);
  a064=(a064*a000);
  a028=(a028-a064);
  a028=(a028/a026);
  a038=(a038-a045);
  a045=(a030*a038);
  a064=(a003*a040);
  a045=(a045-a064);
  a064=(a033*a045);
  a066=(a003*a053);
  a058=(a058-a052);
  a052=(a030*a058);
  a066=(a066+a052);
  a052=(a050*a066);
  a064=(a064-a052);
  a052=(a003+a030);
  a068=(a061*a052);
  a064=(a064+a068);
  a068=(a015*a035);
  a068=(a064+a068);
  a041=(a014*a054);
  a068=(a068+a041);
  a041=(a028*a020);
  a068=(a068-a041);
  a041=casadi_sq(a015);
  a041=(a041*a000);
  a011=(a011-a041);
  a041=casadi_sq(a014);
  a041=(a041*a000);
  a011=(a011-a041);
  a041=casadi_sq(a028);
  a041=(a041*a026);
  a011=(a011-a041);
  a041=(a068/a011);
  a006=(a006/a000);
  a069=(a006*a015);
  a069=(a069*a000);
  a022=(a022-a069);
  a002=(a002/a000);
  a069=(a002*a014);
  a069=(a069*a000);
  a022=(a022-a069);
  a069=(a006*a017);
  a069=(a069*a000);
  a029=(a029-a069);
  a069=(a002*a016);
  a069=(a069*a000);
  a029=(a029-a069);
  a029=(a029/a026);
  a069=(a029*a028);
  a069=(a069*a026);
  a022=(a022-a069);
  a022=(a022/a011);
  a061=(a061*a030);
  a069=(a030*a047);
  a070=(a033*a069);
  a071=(a030*a059);
  a072=(a050*a071);
  a070=(a070+a072);
  a061=(a061-a070);
  a070=(a006*a035);
  a070=(a061+a070);
  a072=(a002*a054);
  a070=(a070+a072);
  a020=(a029*a020);
  a070=(a070-a020);
  a068=(a022*a068);
  a070=(a070-a068);
  a068=casadi_sq(a006);
  a068=(a068*a000);
  a021=(a021-a068);
  a068=casadi_sq(a002);
  a068=(a068*a000);
  a021=(a021-a068);
  a068=casadi_sq(a029);
  a068=(a068*a026);
  a021=(a021-a068);
  a068=casadi_sq(a022);
  a068=(a068*a011);
  a021=(a021-a068);
  a070=(a070/a021);
  a068=(a022*a070);
  a041=(a041-a068);
  a068=(a028*a041);
  a024=(a024-a068);
  a068=(a029*a070);
  a024=(a024-a068);
  a068=(a017*a024);
  a036=(a036+a068);
  a068=(a015*a041);
  a036=(a036+a068);
  a068=(a006*a070);
  a036=(a036+a068);
  a068=(a035*a036);
  a020=(a054/a000);
  a072=(a016*a024);
  a020=(a020+a072);
  a072=(a014*a041);
  a020=(a020+a072);
  a072=(a002*a070);
  a020=(a020+a072);
  a072=(a054*a020);
  a068=(a068+a072);
  a072=(a049*a024);
  a068=(a068+a072);
  a072=(a064*a041);
  a068=(a068+a072);
  a072=(a061*a070);
  a068=(a068+a072);
  a072=arg[9]? arg[9][0] : 0;
  a073=(a033/a072);
  a074=(a033*a073);
  a075=(a050/a072);
  a076=(a050*a075);
  a074=(a074+a076);
  a076=(a019*a063);
  a076=(a076*a032);
  a077=(a033*a065);
  a076=(a076+a077);
  a077=arg[10]? arg[10][0] : 0;
  a078=(a076/a077);
  a079=(a076*a078);
  a074=(a074+a079);
  a068=(a068+a074);
  if (res[1]!=0) res[1][0]=a068;
  a068=arg[12]? arg[12][0] : 0;
  a074=(a068*a024);
  a079=(a008*a036);
  a080=(a004*a020);
  a079=(a079+a080);
  a074=(a074-a079);
  if (res[1]!=0) res[1][1]=a074;
  a074=cos(a005);
  a079=(a074*a055);
  a005=sin(a005);
  a080=(a005*a042);
  a079=(a079-a080);
  a080=arg[12]? arg[12][1] : 0;
  a079=(a079+a080);
  a081=(a079*a024);
  a082=(a005*a036);
  a083=(a074*a020);
  a082=(a082+a083);
  a081=(a081-a082);
  a082=(a005*a040);
  a083=(a074*a053);
  a082=(a082+a083);
  a082=(a082+a080);
  a080=(a082*a041);
  a081=(a081+a080);
  if (res[1]!=0) res[1][2]=a081;
  a081=cos(a010);
  a080=(a081*a060);
  a010=sin(a010);
  a083=(a010*a048);
  a080=(a080-a083);
  a083=arg[12]? arg[12][2] : 0;
  a080=(a080+a083);
  a084=(a080*a024);
  a085=(a010*a036);
  a086=(a081*a020);
  a085=(a085+a086);
  a084=(a084-a085);
  a085=(a081*a058);
  a086=(a010*a038);
  a085=(a085-a086);
  a085=(a085+a083);
  a086=(a085*a041);
  a084=(a084+a086);
  a086=(a010*a047);
  a087=(a081*a059);
  a086=(a086+a087);
  a086=(a086+a083);
  a083=(a086*a070);
  a084=(a084+a083);
  if (res[1]!=0) res[1][3]=a084;
  a084=(a017*a008);
  a084=(a068-a084);
  a083=(a016*a004);
  a084=(a084-a083);
  a083=(a084/a026);
  a087=(a015*a008);
  a088=(a014*a004);
  a087=(a087+a088);
  a088=(a028*a084);
  a087=(a087+a088);
  a088=(a087/a011);
  a087=(a022*a087);
  a089=(a006*a008);
  a090=(a002*a004);
  a089=(a089+a090);
  a084=(a029*a084);
  a089=(a089+a084);
  a087=(a087-a089);
  a087=(a087/a021);
  a089=(a022*a087);
  a088=(a088+a089);
  a089=(a028*a088);
  a083=(a083+a089);
  a089=(a029*a087);
  a083=(a083-a089);
  a089=(a017*a083);
  a084=(a008/a000);
  a089=(a089-a084);
  a084=(a015*a088);
  a089=(a089-a084);
  a084=(a006*a087);
  a089=(a089+a084);
  a084=(a035*a089);
  a090=(a004/a000);
  a091=(a016*a083);
  a090=(a090-a091);
  a091=(a014*a088);
  a090=(a090+a091);
  a091=(a002*a087);
  a090=(a090-a091);
  a091=(a054*a090);
  a084=(a084-a091);
  a091=(a049*a083);
  a084=(a084+a091);
  a091=(a064*a088);
  a084=(a084-a091);
  a091=(a061*a087);
  a084=(a084+a091);
  if (res[1]!=0) res[1][4]=a084;
  a084=(a004*a090);
  a091=(a008*a089);
  a084=(a084-a091);
  a091=(a068*a083);
  a084=(a084+a091);
  if (res[1]!=0) res[1][5]=a084;
  a084=(a074*a090);
  a091=(a005*a089);
  a084=(a084-a091);
  a091=(a079*a083);
  a084=(a084+a091);
  a091=(a082*a088);
  a084=(a084-a091);
  if (res[1]!=0) res[1][6]=a084;
  a084=(a081*a090);
  a091=(a010*a089);
  a084=(a084-a091);
  a091=(a080*a083);
  a084=(a084+a091);
  a091=(a085*a088);
  a084=(a084-a091);
  a091=(a086*a087);
  a084=(a084+a091);
  if (res[1]!=0) res[1][7]=a084;
  a084=(a017*a005);
  a084=(a079-a084);
  a091=(a016*a074);
  a084=(a084-a091);
  a091=(a084/a026);
  a092=(a015*a005);
  a092=(a082-a092);
  a093=(a014*a074);
  a092=(a092-a093);
  a093=(a028*a084);
  a092=(a092-a093);
  a093=(a092/a011);
  a094=(a006*a005);
  a095=(a002*a074);
  a094=(a094+a095);
  a084=(a029*a084);
  a094=(a094+a084);
  a092=(a022*a092);
  a094=(a094+a092);
  a094=(a094/a021);
  a092=(a022*a094);
  a093=(a093+a092);
  a092=(a028*a093);
  a091=(a091-a092);
  a092=(a029*a094);
  a091=(a091+a092);
  a092=(a017*a091);
  a084=(a005/a000);
  a092=(a092-a084);
  a084=(a015*a093);
  a092=(a092+a084);
  a084=(a006*a094);
  a092=(a092-a084);
  a084=(a035*a092);
  a095=(a074/a000);
  a096=(a016*a091);
  a095=(a095-a096);
  a096=(a014*a093);
  a095=(a095-a096);
  a096=(a002*a094);
  a095=(a095+a096);
  a096=(a054*a095);
  a084=(a084-a096);
  a096=(a049*a091);
  a084=(a084+a096);
  a096=(a064*a093);
  a084=(a084+a096);
  a096=(a061*a094);
  a084=(a084-a096);
  if (res[1]!=0) res[1][8]=a084;
  a084=(a004*a095);
  a096=(a008*a092);
  a084=(a084-a096);
  a096=(a068*a091);
  a084=(a084+a096);
  if (res[1]!=0) res[1][9]=a084;
  a084=(a074*a095);
  a096=(a005*a092);
  a084=(a084-a096);
  a096=(a079*a091);
  a084=(a084+a096);
  a096=(a082*a093);
  a084=(a084+a096);
  if (res[1]!=0) res[1][10]=a084;
  a084=(a081*a095);
  a096=(a010*a092);
  a084=(a084-a096);
  a096=(a080*a091);
  a084=(a084+a096);
  a096=(a085*a093);
  a084=(a084+a096);
  a096=(a086*a094);
  a084=(a084-a096);
  if (res[1]!=0) res[1][11]=a084;
  a084=(a017*a010);
  a084=(a080-a084);
  a096=(a016*a081);
  a084=(a084-a096);
  a096=(a084/a026);
  a097=(a015*a010);
  a097=(a085-a097);
  a098=(a014*a081);
  a097=(a097-a098);
  a098=(a028*a084);
  a097=(a097-a098);
  a098=(a097/a011);
  a099=(a006*a010);
  a099=(a086-a099);
  a100=(a002*a081);
  a099=(a099-a100);
  a084=(a029*a084);
  a099=(a099-a084);
  a097=(a022*a097);
  a099=(a099-a097);
  a099=(a099/a021);
  a097=(a022*a099);
  a098=(a098-a097);
  a097=(a028*a098);
  a096=(a096-a097);
  a097=(a029*a099);
  a096=(a096-a097);
  a097=(a017*a096);
  a084=(a010/a000);
  a097=(a097-a084);
  a084=(a015*a098);
  a097=(a097+a084);
  a084=(a006*a099);
  a097=(a097+a084);
  a084=(a035*a097);
  a100=(a081/a000);
  a101=(a016*a096);
  a100=(a100-a101);
  a101=(a014*a098);
  a100=(a100-a101);
  a101=(a002*a099);
  a100=(a100-a101);
  a101=(a054*a100);
  a084=(a084-a101);
  a101=(a049*a096);
  a084=(a084+a101);
  a101=(a064*a098);
  a084=(a084+a101);
  a101=(a061*a099);
  a084=(a084+a101);
  if (res[1]!=0) res[1][12]=a084;
  a084=(a004*a100);
  a101=(a008*a097);
  a084=(a084-a101);
  a101=(a068*a096);
  a084=(a084+a101);
  if (res[1]!=0) res[1][13]=a084;
  a084=(a074*a100);
  a101=(a005*a097);
  a084=(a084-a101);
  a101=(a079*a096);
  a084=(a084+a101);
  a101=(a082*a098);
  a084=(a084+a101);
  if (res[1]!=0) res[1][14]=a084;
  a084=(a081*a100);
  a101=(a010*a097);
  a084=(a084-a101);
  a101=(a080*a096);
  a084=(a084+a101);
  a101=(a085*a098);
  a084=(a084+a101);
  a101=(a086*a099);
  a084=(a084+a101);
  if (res[1]!=0) res[1][15]=a084;
  a084=arg[1]? arg[1][3] : 0;
  a101=arg[1]? arg[1][2] : 0;
  a102=(a084+a101);
  a103=casadi_sq(a102);
  a104=(a103*a053);
  a105=casadi_sq(a101);
  a106=(a105*a025);
  a104=(a104+a106);
  a106=arg[6]? arg[6][1] : 0;
  a107=(a104*a106);
  a108=(a103*a057);
  a104=(a104+a108);
  a108=arg[1]? arg[1][4] : 0;
  a102=(a102+a108);
  a102=casadi_sq(a102);
  a109=(a059*a102);
  a104=(a104+a109);
  a109=arg[6]? arg[6][2] : 0;
  a104=(a104*a109);
  a110=(a107+a104);
  a111=(a110/a000);
  a112=(a017*a110);
  a113=(a027+a037);
  a114=(a040+a113);
  a115=(a044+a114);
  a116=(a047+a115);
  a116=(a104*a116);
  a117=(a103*a040);
  a027=(a105*a027);
  a117=(a117+a027);
  a044=(a103*a044);
  a044=(a117+a044);
  a027=(a047*a102);
  a044=(a044+a027);
  a025=(a025+a051);
  a027=(a053+a025);
  a057=(a057+a027);
  a118=(a059+a057);
  a118=(a044*a118);
  a118=(a118*a109);
  a116=(a116-a118);
  a117=(a117*a106);
  a027=(a117*a027);
  a027=(a116-a027);
  a107=(a107*a114);
  a027=(a027+a107);
  a037=(a110*a037);
  a037=(a027-a037);
  a044=(a044*a109);
  a117=(a117+a044);
  a051=(a117*a051);
  a037=(a037+a051);
  a112=(a112-a037);
  a037=(a016*a117);
  a112=(a112-a037);
  a026=(a112/a026);
  a037=arg[2]? arg[2][0] : 0;
  a113=(a110*a113);
  a027=(a027-a113);
  a025=(a117*a025);
  a027=(a027+a025);
  a037=(a037-a027);
  a027=(a015*a110);
  a037=(a037+a027);
  a027=(a014*a117);
  a037=(a037-a027);
  a027=(a028*a112);
  a037=(a037-a027);
  a011=(a037/a011);
  a027=arg[2]? arg[2][1] : 0;
  a104=(a104*a115);
  a116=(a116-a104);
  a044=(a044*a057);
  a116=(a116+a044);
  a027=(a027-a116);
  a110=(a006*a110);
  a027=(a027+a110);
  a110=(a002*a117);
  a027=(a027-a110);
  a112=(a029*a112);
  a027=(a027-a112);
  a037=(a022*a037);
  a027=(a027-a037);
  a027=(a027/a021);
  a022=(a022*a027);
  a011=(a011-a022);
  a028=(a028*a011);
  a026=(a026-a028);
  a029=(a029*a027);
  a026=(a026-a029);
  a017=(a017*a026);
  a111=(a111+a017);
  a015=(a015*a011);
  a111=(a111+a015);
  a006=(a006*a027);
  a111=(a111+a006);
  a035=(a035*a111);
  a117=(a117/a000);
  a016=(a016*a026);
  a117=(a117-a016);
  a014=(a014*a011);
  a117=(a117-a014);
  a002=(a002*a027);
  a117=(a117-a002);
  a054=(a054*a117);
  a035=(a035-a054);
  a049=(a049*a026);
  a035=(a035+a049);
  a064=(a064*a011);
  a035=(a035+a064);
  a061=(a061*a027);
  a035=(a035+a061);
  a061=arg[5]? arg[5][1] : 0;
  a061=(a061/a072);
  a064=(a050*a061);
  a049=arg[5]? arg[5][0] : 0;
  a049=(a049/a072);
  a072=(a033*a049);
  a064=(a064-a072);
  a072=arg[5]? arg[5][2] : 0;
  a072=(a072/a077);
  a076=(a076*a072);
  a064=(a064+a076);
  a035=(a035+a064);
  a064=arg[1]? arg[1][0] : 0;
  a076=(a034*a064);
  a043=(a043*a101);
  a076=(a076+a043);
  a045=(a045*a084);
  a076=(a076+a045);
  a069=(a069*a108);
  a076=(a076-a069);
  a076=(a050*a076);
  a069=(a034*a101);
  a052=(a052*a084);
  a069=(a069+a052);
  a052=(a030*a108);
  a069=(a069+a052);
  a052=(a076*a069);
  a039=(a103*a039);
  a045=(a007*a039);
  a105=(a105*a023);
  a023=(a004*a105);
  a045=(a045+a023);
  a023=(a045*a003);
  a103=(a103*a018);
  a007=(a007*a103);
  a007=(a045+a007);
  a046=(a046*a102);
  a013=(a013*a046);
  a007=(a007+a013);
  a013=(a007*a030);
  a023=(a023+a013);
  a023=(a033*a023);
  a052=(a052-a023);
  a023=arg[1]? arg[1][1] : 0;
  a034=(a034*a023);
  a056=(a056*a101);
  a034=(a034+a056);
  a066=(a066*a084);
  a034=(a034+a066);
  a071=(a071*a108);
  a034=(a034+a071);
  a034=(a033*a034);
  a071=(a034*a069);
  a052=(a052+a071);
  a076=(a076+a034);
  a065=(a065*a050);
  a063=(a033*a063);
  a034=(a065-a063);
  a071=arg[4]? arg[4][2] : 0;
  a066=(a034*a071);
  a076=(a076+a066);
  a066=arg[4]? arg[4][0] : 0;
  a066=(a050*a066);
  a076=(a076-a066);
  a056=arg[4]? arg[4][1] : 0;
  a033=(a033*a056);
  a076=(a076-a033);
  a056=(a067*a050);
  a013=(a031*a062);
  a013=(a013*a032);
  a056=(a056-a013);
  a013=(a056*a069);
  a076=(a076-a013);
  a076=(a069*a076);
  a052=(a052+a076);
  a034=(a034*a069);
  a063=(a063-a065);
  a063=(a071*a063);
  a034=(a034+a063);
  a071=(a071*a034);
  a052=(a052+a071);
  a066=(a066*a069);
  a052=(a052-a066);
  a033=(a033*a069);
  a052=(a052-a033);
  a039=(a039*a009);
  a105=(a105*a008);
  a039=(a039+a105);
  a003=(a039*a003);
  a103=(a103*a009);
  a103=(a039+a103);
  a046=(a046*a012);
  a103=(a103+a046);
  a030=(a103*a030);
  a003=(a003+a030);
  a050=(a050*a003);
  a052=(a052+a050);
  a035=(a035+a052);
  if (res[2]!=0) res[2][0]=a035;
  a035=(a004*a117);
  a052=(a008*a111);
  a035=(a035-a052);
  a068=(a068*a026);
  a035=(a035+a068);
  a008=(a008*a023);
  a008=(a008*a101);
  a004=(a004*a064);
  a004=(a004*a101);
  a008=(a008+a004);
  a035=(a035-a008);
  if (res[2]!=0) res[2][1]=a035;
  a035=(a074*a117);
  a008=(a005*a111);
  a035=(a035-a008);
  a079=(a079*a026);
  a035=(a035+a079);
  a082=(a082*a011);
  a035=(a035+a082);
  a045=(a005*a045);
  a039=(a074*a039);
  a045=(a045-a039);
  a055=(a055*a101);
  a055=(a023+a055);
  a053=(a053*a084);
  a055=(a055+a053);
  a005=(a005*a055);
  a055=(a101+a084);
  a005=(a005*a055);
  a045=(a045-a005);
  a042=(a042*a101);
  a042=(a064+a042);
  a040=(a040*a084);
  a042=(a042-a040);
  a074=(a074*a042);
  a074=(a074*a055);
  a045=(a045-a074);
  a035=(a035+a045);
  if (res[2]!=0) res[2][2]=a035;
  a035=(a081*a117);
  a045=(a010*a111);
  a035=(a035-a045);
  a080=(a080*a026);
  a035=(a035+a080);
  a085=(a085*a011);
  a035=(a035+a085);
  a086=(a086*a027);
  a035=(a035+a086);
  a007=(a010*a007);
  a103=(a081*a103);
  a007=(a007-a103);
  a060=(a060*a101);
  a023=(a023+a060);
  a058=(a058*a084);
  a023=(a023+a058);
  a059=(a059*a108);
  a023=(a023+a059);
  a010=(a010*a023);
  a055=(a055+a108);
  a010=(a010*a055);
  a007=(a007-a010);
  a048=(a048*a101);
  a064=(a064+a048);
  a038=(a038*a084);
  a064=(a064+a038);
  a047=(a047*a108);
  a064=(a064-a047);
  a081=(a081*a064);
  a081=(a081*a055);
  a007=(a007-a081);
  a035=(a035+a007);
  if (res[2]!=0) res[2][3]=a035;
  if (res[3]!=0) res[3][0]=a111;
  if (res[3]!=0) res[3][1]=a117;
  if (res[3]!=0) res[3][2]=a026;
  if (res[3]!=0) res[3][3]=a011;
  if (res[3]!=0) res[3][4]=a027;
  if (res[4]!=0) res[4][0]=a049;
  if (res[4]!=0) res[4][1]=a061;
  if (res[4]!=0) res[4][2]=a072;
  if (res[5]!=0) res[5][0]=a036;
  a020=(-a020);
  if (res[5]!=0) res[5][1]=a020;
  if (res[5]!=0) res[5][2]=a024;
  if (res[5]!=0) res[5][3]=a041;
  if (res[5]!=0) res[5][4]=a070;
  if (res[5]!=0) res[5][5]=a089;
  if (res[5]!=0) res[5][6]=a090;
  if (res[5]!=0) res[5][7]=a083;
  a088=(-a088);
  if (res[5]!=0) res[5][8]=a088;
  if (res[5]!=0) res[5][9]=a087;
  if (res[5]!=0) res[5][10]=a092;
  if (res[5]!=0) res[5][11]=a095;
  if (res[5]!=0) res[5][12]=a091;
  if (res[5]!=0) res[5][13]=a093;
  a094=(-a094);
  if (res[5]!=0) res[5][14]=a094;
  if (res[5]!=0) res[5][15]=a097;
  if (res[5]!=0) res[5][16]=a100;
  if (res[5]!=0) res[5][17]=a096;
  if (res[5]!=0) res[5][18]=a098;
  if (res[5]!=0) res[5][19]=a099;
  a073=(-a073);
  if (res[6]!=0) res[6][0]=a073;
  if (res[6]!=0) res[6][1]=a075;
  if (res[6]!=0) res[6][2]=a078;
  if (res[6]!=0) res[6][3]=a001;
  if (res[6]!=0) res[6][4]=a001;
  if (res[6]!=0) res[6][5]=a001;
  if (res[6]!=0) res[6][6]=a001;
  if (res[6]!=0) res[6][7]=a001;
  if (res[6]!=0) res[6][8]=a001;
  if (res[6]!=0) res[6][9]=a001;
  if (res[6]!=0) res[6][10]=a001;
  if (res[6]!=0) res[6][11]=a001;
  if (res[7]!=0) res[7][0]=a056;
  a031=(a031*a067);
  a019=(a019*a062);
  a031=(a031+a019);
  if (res[8]!=0) res[8][0]=a031;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_contact_system_n_in(void) { return 13;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_contact_system_n_out(void) { return 9;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na2_contact_system_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_contact_system_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "tau";
    case 3: return "q_obj";
    case 4: return "v_obj";
    case 5: return "f_obj";
    case 6: return "K";
    case 7: return "contact_link";
    case 8: return "side";
    case 9: return "object_mass";
    case 10: return "object_inertia";
    case 11: return "rho";
    case 12: return "wheel_offset";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_contact_system_name_out(casadi_int i) {
  switch (i) {
    case 0: return "M";
    case 1: return "delassus";
    case 2: return "b";
    case 3: return "qdd_free";
    case 4: return "a_obj_free";
    case 5: return "qdd_from_lam";
    case 6: return "a_obj_from_lam";
    case 7: return "gap";
    case 8: return "s";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_contact_system_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s2;
    case 4: return casadi_s2;
    case 5: return casadi_s2;
    case 6: return casadi_s3;
    case 7: return casadi_s2;
    case 8: return casadi_s4;
    case 9: return casadi_s4;
    case 10: return casadi_s4;
    case 11: return casadi_s1;
    case 12: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_contact_system_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s6;
    case 2: return casadi_s7;
    case 3: return casadi_s0;
    case 4: return casadi_s2;
    case 5: return casadi_s8;
    case 6: return casadi_s9;
    case 7: return casadi_s4;
    case 8: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13;
  if (sz_res) *sz_res = 9;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 9*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na2_batch_contact_system(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[13];
  casadi_real* r[9];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 120);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 13; ++k) a[k] = 0;
  for (k = 0; k < 9; ++k) r[k] = 0;
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
    a[11] = arg[11] + i * stride[11];
    a[12] = arg[12] + i * stride[12];
    r[0] = res[0] + i * 25;
    r[1] = res[1] + i * 16;
    r[2] = res[2] + i * 4;
    r[3] = res[3] + i * 5;
    r[4] = res[4] + i * 3;
    r[5] = res[5] + i * 20;
    r[6] = res[6] + i * 12;
    r[7] = res[7] + i * 1;
    r[8] = res[8] + i * 1;
    if (snakecg_na2_contact_system(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
