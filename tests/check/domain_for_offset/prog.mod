MODULE prog
  ! The robot's position is read back only to move again, shifted by a group input's value
  ! times a FOR variable. The FOR runs from 1 to reach, routine data nothing writes: the
  ! offset is at most about 4.3E12, far below 2^64, and the input takes one value (0).
  VAR signalgi gi_step;
  VAR robtarget here;
  PROC main()
    AliasIO "GI_STEP", gi_step;
    WHILE TRUE DO
      Approach;
    ENDWHILE
  ENDPROC
  PROC Approach()
    VAR num reach := 1000;
    FOR i FROM 1 TO reach STEP 500 DO
      here := CRobT();
      MoveL Offs(here, 0, 0, GInput(gi_step) * i), v100, fine, tool0;
    ENDFOR
  ENDPROC
ENDMODULE
