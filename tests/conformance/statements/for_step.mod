MODULE for_step
  ! Tests: FOR with STEP 2 visits 1, 3, 5, 7 and stops when the variable
  ! leaves the range (7 + 2 > 8).
  PROC main()
    FOR i FROM 1 TO 8 STEP 2 DO
      TPWrite "i=" \Num:=i;
    ENDFOR
  ENDPROC
ENDMODULE
