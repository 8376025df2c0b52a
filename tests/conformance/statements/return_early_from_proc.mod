MODULE return_early_from_proc
  ! Tests: RETURN in a procedure ends it at once (also from inside a loop)
  ! and the caller continues after the call.
  PROC find(num target)
    FOR i FROM 1 TO 10 DO
      IF i = target THEN
        TPWrite "found " \Num:=i;
        RETURN;
      ENDIF
    ENDFOR
    TPWrite "not found";
  ENDPROC
  PROC main()
    find 3;
    find 20;
    TPWrite "back in main";
  ENDPROC
ENDMODULE
