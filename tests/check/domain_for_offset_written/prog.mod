MODULE prog
  ! The robot's position is read back only to move again, shifted by a group input's value
  ! times a FOR variable. The FOR runs up to reach, routine data the routine writes (1E28
  ! after its initial 1000): the offset may pass 2^64 and the height leave the range of num
  ! turn after turn, so the input gets no default domain.
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
    reach := 1E28;
    FOR i FROM 1 TO reach STEP reach DO
      here := CRobT();
      MoveL Offs(here, 0, 0, GInput(gi_step) * i), v100, fine, tool0;
    ENDFOR
  ENDPROC
ENDMODULE
