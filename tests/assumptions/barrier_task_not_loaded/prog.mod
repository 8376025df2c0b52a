MODULE MeetsThePress
    ! Issue 28: robot 1 meets the press task and the gripper task at a barrier; only
    ! robot 1's module is given, so both partners are taken as arriving at once. The
    ! verdicts say so, naming the barrier and the tasks it waits for.
    VAR syncident press_open;
    PERS tasks cell{3} := [["T_ROB1"], ["T_PRESS"], ["T_GRIP"]];
    VAR num parts := 0;

    PROC main()
        WaitSyncTask press_open, cell;
        parts := parts + 1;
    ENDPROC
ENDMODULE
