MODULE controllers_load
  ! Tests: code that controllers load (issue 19) loads and runs: SearchL supervising a PERS
  ! bool (PersFlag) instead of a signal, UIMsgBox \Result into a PERS, tool0/wobj0/load0 given
  ! to PERS parameters of the program's own routines, pos / num, an aggregate added to a pos, ReadStr \Delim
  ! \DiscardHeaders, StrFormat {n} \Argn, GetSysInfo \SWVersionName, menudata as a value
  ! record (its text `.description`), EGMSetupUC \PathCorr \APTR and EGMRunPose \Offset (a pose), a world zone
  ! declared PERS with a value as in the manual's examples.
  TASK PERS menudata mdHome := ["Move to Home","","MoveToHome",1,"",255,TRUE,1,0,FALSE,210];
  PERS bool bTouched := TRUE;
  PERS wzstationary wzHome := [0];
  PERS btnres pAnswer := 0;
  PERS robtarget pEnd := [[500,0,100],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget pFound;
  VAR pos pMid;
  VAR iodev file;
  VAR egmident egmId;
  VAR pose offset := [[0,0,5],[1,0,0,0]];

  PROC main()
    SearchL \Stop, bTouched, pFound, pEnd, v50, tool0;
    TPWrite "found at z " \Num:=pFound.trans.z;
    UIMsgBox "continue?" \Buttons:=btnOKCancel \Result:=pAnswer;
    TPWrite "answer " \Num:=pAnswer;
    Describe tool0, wobj0, load0;
    pMid := (pEnd.trans + pFound.trans) / 4;
    TPWrite "mid " \Pos:=pMid;
    pMid := [10,10,30] + pMid;
    TPWrite "above " \Pos:=pMid;
    Open "HOME:/recipe.txt", file \Read;
    TPWrite ReadStr(file \Delim:=",");
    TPWrite ReadStr(file \Delim:=",");
    TPWrite ReadStr(file \Delim:="," \DiscardHeaders);
    Close file;
    TPWrite StrFormat("part_{1}_of_{2}" \Arg1:=NumToStr(3,0) \Arg2:="7");
    TPWrite GetSysInfo(\SWVersionName);
    TPWrite mdHome.c3 + " " + NumToStr(mdHome.c11, 0);
    mdHome.description := mdHome.description + " (service)";
    TPWrite mdHome.description;
    TPWrite "zone " \Num:=wzHome.wz;
    EGMGetId egmId;
    EGMSetupUC ROB_1, egmId, "path_corr", "UCdevice" \PathCorr \APTR;
    EGMRunPose egmId, EGM_STOP_HOLD \x \y \z \Offset:=offset;
  ENDPROC

  PROC Describe(PERS tooldata tool, PERS wobjdata wobj, PERS loaddata load)
    TPWrite "tool mass " \Num:=tool.tload.mass;
    TPWrite "wobj ufprog " \Bool:=wobj.ufprog;
    TPWrite "load mass " \Num:=load.mass;
  ENDPROC
ENDMODULE
