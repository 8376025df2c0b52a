MODULE for_negative_step
  ! Tests: FOR with a negative STEP counts down: 5, 3, 1.
  PROC main()
    FOR i FROM 5 TO 1 STEP -2 DO
      TPWrite "i=" \Num:=i;
    ENDFOR
  ENDPROC
ENDMODULE
