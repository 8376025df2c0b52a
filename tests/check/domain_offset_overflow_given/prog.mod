MODULE prog
  ! The robot's position is read back only to move again, shifted by a group input's value
  ! times 1E28.  The product stays a num (at most about 4.3E37), but added to the height
  ! on every turn it leaves the range of num after a few turns (ERR_NUM_LIMIT) for a large
  ! input, never for 0.  An offset of Offs that large gets no default domain.  Before, the
  ! input took one value (0) and no_runtime_error came out HOLDS; with --input-domain
  ! GI_STEP=0,4000000000 it is VIOLATED.
  VAR signalgi gi_step;
  VAR robtarget here;
  PROC main()
    AliasIO "GI_STEP", gi_step;
    WHILE TRUE DO
      here := CRobT();
      MoveL Offs(here, 0, 0, GInput(gi_step) * 1E28), v100, fine, tool0;
    ENDWHILE
  ENDPROC
ENDMODULE
