MODULE for_single_iteration
  ! Tests: FOR with FROM equal to TO runs the body exactly once.
  PROC main()
    FOR i FROM 4 TO 4 DO
      TPWrite "i=" \Num:=i;
    ENDFOR
  ENDPROC
ENDMODULE
