MODULE StationMenu
  ! Tests: stubs for an operator menu whose station library was not given: procedures with
  ! switches from several calls, a function in a condition, work objects passed to a missing
  ! procedure (no use tells their type: the name's prefix 'wobj' does, and the comment says
  ! so), the procedure's parameter then typed from them.
  PROC main()
    LogEvent "Main", 18, "PP to main";
    IF StationsReady() THEN
      GoHome \ArmOnly;
    ELSE
      GoHome \ArmFirst;
    ENDIF
    TEST UIMessageBox(\Header:="Align" \BtnArray:=["Station 1", "Station 2", "", "", ""])
    CASE 1:
      AlignStation wobjStation1;
    CASE 2:
      AlignStation wobjStation2;
    ENDTEST
  ENDPROC
ENDMODULE
