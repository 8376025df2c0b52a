MODULE Outcomes
  ! Tests: the controller's or operator's decisions are nondeterministic when model checking:
  ! a search hits or misses, an operator presses any shown button, a file exists or not, a
  ! camera finds 0..2 parts.  Each result lands in a PERS the properties name.
  PERS num nSearch := 0;
  PERS num nButton := 0;
  PERS num nFile := 0;
  PERS num nParts := -1;
  PERS num nFlagSearch := 0;
  PERS num nReach := 0;
  PERS bool bTouch := FALSE;
  VAR errnum errIk;
  VAR jointtarget jIk;
  PERS robtarget pEnd := [[500,0,100],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget pFound;
  VAR cameradev camTop;

  PROC main()
    Probe;
    nButton := UIMessageBox(\Header:="Next" \Buttons:=btnYesNoCancel);
    IF IsFile("HOME:/recipe.txt") THEN
      nFile := 1;
    ELSE
      nFile := 2;
    ENDIF
    nParts := CamNumberOfResults(camTop);
    FlagProbe;
    jIk := CalcJointT(pEnd, tool0 \ErrorNumber:=errIk);
    IF errIk = ERR_ROBLIMIT THEN
      nReach := 2;
    ELSE
      nReach := 1;
    ENDIF
  ENDPROC

  PROC FlagProbe()
    ! issue 19: a PERS bool supervised instead of a signal (SearchL's PersFlag)
    SearchL \Stop, bTouch, pFound, pEnd, v50, tool0;
    nFlagSearch := 1;
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      nFlagSearch := 2;
      RETURN;
    ENDIF
  ENDPROC

  PROC Probe()
    SearchL \Stop, diProbe, pFound, pEnd, v50, tool0;
    nSearch := 1;
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      nSearch := 2;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
