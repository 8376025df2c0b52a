MODULE MainModule
  ! Tests: each TPWrite produces exactly one line, in execution order.
  PROC main()
    FOR i FROM 1 TO 3 DO
      TPWrite "line " \Num:=i;
    ENDFOR
    TPWrite "done";
  ENDPROC
ENDMODULE
