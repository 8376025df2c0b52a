MODULE Cell
  ! A cell program whose operator starts two routines by hand (PP to routine): the
  ! calibration divides by a count the program never set, a run-time error only that
  ! entry reaches.
  VAR num cycles := 0;
  VAR num parts := 0;
  VAR num ratio := 0;

  PROC main()
    cycles := cycles + 1;
    IF cycles > 3 cycles := 0;
    Count 1;
  ENDPROC

  PROC Count(num step_size)
    parts := parts + step_size;
  ENDPROC

  PROC CalibrateCamera()
    ratio := cycles / parts;
  ENDPROC

  PROC TestGripper()
    TPWrite "gripper test";
  ENDPROC

  PROC Unused(num offset)
    TPWrite "never called";
  ENDPROC
ENDMODULE
