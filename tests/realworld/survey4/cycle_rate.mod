MODULE CycleRate
    ! Parts per hour from the measured cycle time, in the style of cycle-time demo programs:
    ! a clock is reset and started, the cycle runs, the clock is stopped and read, and the
    ! rate is 3600 divided by the reading.
    VAR clock cycle_watch;
    VAR num cycle_secs := 0;
    VAR num parts_per_hour := 0;
    VAR num slow_cycles := 0;
    CONST robtarget pick := [[400,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place := [[400,300,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ClkReset cycle_watch;
        ClkStart cycle_watch;
        MoveJ pick, v1000, fine, tool0;
        WaitTime 0.5;
        MoveJ place, v1000, fine, tool0;
        ClkStop cycle_watch;
        cycle_secs := ClkRead(cycle_watch);
        parts_per_hour := Round(3600 / cycle_secs \Dec:=1);
        IF cycle_secs > 30 THEN
            slow_cycles := slow_cycles + 1;
            TPWrite "Cycle too slow: " \Num:=cycle_secs;
        ENDIF
        TPWrite "Parts per hour: " \Num:=parts_per_hour;
    ENDPROC
ENDMODULE
