MODULE prog
  ! A PLC's speed override, read from a group input, given to SpeedRefresh. Outside 0-100 %
  ! the controller raises ERR_SPEED_REFRESH_LIM, and nothing handles it. Before, SpeedRefresh
  ! had no effect and the input one value (0): no_runtime_error came out HOLDS.
  VAR signalgi gi_override;
  PROC main()
    AliasIO "GI_OVERRIDE", gi_override;
    SpeedRefresh GInput(gi_override);
  ENDPROC
ENDMODULE
