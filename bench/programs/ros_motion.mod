MODULE ros_motion
  ! Motion task of the ROS-style server: runs each trajectory the socket task
  ! completes, then hands the buffer back.
  PROC main()
    WHILE TRUE DO
      WaitUntil trajReady;
      WaitTestAndSet trajLock;
      ! (FOR i FROM 1 TO 0 would count down: 1, 0)
      IF trajSize > 0 THEN
        FOR i FROM 1 TO trajSize DO
          MoveAbsJ trajBuffer{i}, v1000, z10, tool0;
        ENDFOR
      ENDIF
      nExecuted := (nExecuted + 1) MOD 3;
      trajSize := 0;
      trajLock := FALSE;
      trajReady := FALSE;
    ENDWHILE
  ENDPROC
ENDMODULE
