MODULE MainModule
  ! Tests: a search that sees no signal change raises ERR_WHLSEARCH (manual: no search hit);
  ! the ERROR handler takes it, as cells do to report a missing part.
  PERS robtarget pEnd := [[500,0,100],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget pFound;
  PROC main()
    SearchL \SStop, diProbe \PosFlank, pFound, pEnd, v50, tool0 \WObj:=wobj0;
    TPWrite "part found";
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      TPWrite "no part: search missed";
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
