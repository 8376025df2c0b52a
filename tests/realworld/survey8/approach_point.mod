MODULE ApproachPoint
  ! Our own program in the style of a camera-calibration routine (survey round 8): a target's
  ! position is built from an aggregate whose first part is data of a module not given.
  VAR robtarget pApproach := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR num nHeight := 250;

  PROC main()
    pApproach.trans := [xCameraOffset, 0, nHeight];
  ENDPROC
ENDMODULE
