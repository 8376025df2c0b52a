MODULE SeamTracking
  ! Our own program in the style of an ArcWare cell (survey round 8): seam-tracking and
  ! adaptive-fill data of the welding option, whose types no module given declares, set
  ! with nested aggregates; a layer counter picks the tracking data per pass.
  TASK PERS trackdata trackRoot := [0,TRUE,50,[0,0,0,0,0,0,0,0,0],[0,0,0,0,0,0,0]];
  TASK PERS trackdata trackFill := [0,TRUE,80,[0,0,1,0,0,0,0,0,0],[0,0,0,0,0,0,0]];
  TASK PERS trackdata trackActive := [0,FALSE,0,[0,0,0,0,0,0,0,0,0],[0,0,0,0,0,0,0]];
  VAR num nPass := 0;

  PROC main()
    FOR pass FROM 1 TO 3 DO
      nPass := pass;
      IF pass = 1 THEN
        trackActive := trackRoot;
      ELSE
        trackActive := trackFill;
      ENDIF
    ENDFOR
  ENDPROC
ENDMODULE
