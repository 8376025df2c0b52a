MODULE CellTypes
    ! A cell record whose components have types of a module that was not given
    ! (the gripper and the feeder are declared in their own modules on the controller).
    RECORD cell_state
        gripper_cfg gripper;
        feeder_cfg feeder;
        num parts_done;
    ENDRECORD

    VAR cell_state cell;

    PROC main()
        cell.parts_done := 0;
        WHILE cell.parts_done < 3 DO
            Incr cell.parts_done;
        ENDWHILE
        TPWrite "parts: "\Num:=cell.parts_done;
    ENDPROC
ENDMODULE
